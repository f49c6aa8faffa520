#!/bin/sh
# SPDX-License-Identifier: MIT
# The core must build freestanding with no floating-point registers (a float
# or double is then a compile error) and reference nothing from libc but mem*.
# FX_FS_FLAGS replaces the float-ban flags for targets where
# -mgeneral-regs-only does not exist (32-bit ARM: -mfloat-abi=soft, where any
# float would instead call a helper such as __aeabi_fadd, caught by nm below).
cc=$1; nm=$2; out=$3; shift 3
flags=${FX_FS_FLAGS:--ffreestanding -mgeneral-regs-only}
mkdir -p "$out"
P=0; F=0
for src in "$@"; do
    o="$out/$(basename "$src" .c).o"
    if $cc -std=c11 -Wall -Wextra -Werror -O2 $flags \
        -Ikernel-free-src/include -c "$src" -o "$o" 2> "$o.err"; then
        P=$((P + 1))
    else
        echo "FAIL freestanding compile: $src"; cat "$o.err"; F=$((F + 1))
    fi
done
bad=$(grep -nE '#include *<(linux/|sys/|stdio|stdlib|math\.h|unistd|fcntl|errno|pthread|time\.h|signal)' \
      $(find kernel-free-src -name "*.[ch]"))
if [ -n "$bad" ]; then echo "FAIL forbidden include in the core:"; echo "$bad"; F=$((F + 1)); else P=$((P + 1)); fi
undef=$($nm -u "$out"/*.o | awk 'NF == 2 && $1 == "U" {print $2} NF == 1 && $1 !~ /:$/ {print $1}' | sort -u)
defined=$($nm --defined-only "$out"/*.o | awk 'NF == 3 {print $3}' | sort -u)
extern=$(echo "$undef" | while read -r s; do
    [ -z "$s" ] && continue
    echo "$defined" | grep -qx "$s" && continue
    # mem* from libc; the compiler's own integer helpers from libgcc (64-bit
    # division and shifts on 32-bit ARM, division on ARMv6 which has no
    # divide instruction) are part of a freestanding implementation.
    case "$s" in
    memset|memcpy|memmove|memcmp|_GLOBAL_OFFSET_TABLE_) ;;
    __aeabi_idiv|__aeabi_uidiv|__aeabi_idivmod|__aeabi_uidivmod|__aeabi_ldivmod|__aeabi_uldivmod) ;;
    __aeabi_llsl|__aeabi_llsr|__aeabi_lasr|__aeabi_lmul|__aeabi_lcmp|__aeabi_ulcmp) ;;
    __divdi3|__udivdi3|__moddi3|__umoddi3|__divmoddi4|__udivmoddi4|__clzsi2|__clzdi2|__ctzdi2) ;;
    __popcountsi2|__popcountdi2|__ashldi3|__ashrdi3|__lshrdi3|__muldi3|__aeabi_unwind_cpp_pr0) ;;
    *) echo "$s";; esac
done)
if [ -n "$extern" ]; then echo "FAIL core objects reference outside symbols:"; echo "$extern"; F=$((F + 1)); else P=$((P + 1)); fi
# No floating-point helper of any ABI (soft-float builds would call these).
fp=$($nm "$out"/*.o | grep -E ' U (__aeabi_[fd]|__.*[sd]f[23]|__float|__fix|__extend|__trunc)' || true)
if [ -n "$fp" ]; then echo "FAIL floating-point helpers in the core:"; echo "$fp"; F=$((F + 1)); else P=$((P + 1)); fi
echo "freestanding: $P passed, $F failed"
[ "$F" -eq 0 ]
