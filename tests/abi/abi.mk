# SPDX-License-Identifier: MIT
# The library's face (issue #20): exported symbols = public headers, soname,
# version macros, SPDX lines, extern "C" guards (tests/abi/abi.sh), and every
# public header from C++ against libfixel.a and libfixel.so (tests/cxx/cxx.sh).
TEST_DEB_PKGS += g++
TEST_SUITES += "sh tests/abi/abi.sh $(BUILD) $(VERSION) $(SOMAJOR) $(NM)" \
               "sh tests/cxx/cxx.sh $(BUILD) '$(LDLIBS)'"
.PHONY: test-abi
test-abi: all
	@bash tests/run-suites.sh "sh tests/abi/abi.sh $(BUILD) $(VERSION) $(SOMAJOR) $(NM)" "sh tests/cxx/cxx.sh $(BUILD) '$(LDLIBS)'"
