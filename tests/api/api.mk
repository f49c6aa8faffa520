# SPDX-License-Identifier: MIT
# The API reference (man pages and docs/api/ from the header comments,
# tools/gen/apiref.sh) is complete and current (tests/api/api.sh).
TEST_SUITES += "sh tests/api/api.sh '$(CC)'"
TEST_DEB_PKGS += man-db
.PHONY: test-api api-html
test-api:
	@sh tests/run-suites.sh "sh tests/api/api.sh '$(CC)'"
# Rewrite docs/api/ after changing a public header's comments.
api-html:
	sh tools/gen/apiref.sh --html docs/api
