#!/bin/sh
# SPDX-License-Identifier: MIT
# Cross-builds fixel's test suites for each Pi architecture and runs them
# under qemu-user. An architecture whose toolchain, emulator or target
# libraries are missing is skipped with the reason (tests/arm/deps.sh installs
# them when run as root); one that builds must pass.
# ARM_BOARDS="rpi-zero ..." runs only those boards (default: every one).
P=0; F=0
# (make test runs one board per suite, side by side: one deps.sh at a time)
if [ "$(id -u)" = 0 ]; then mkdir -p build; flock build/.arm-deps.lock sh tests/arm/deps.sh; fi
run_suite() { # label, command...
    label=$1; shift
    out=$("$@" 2>&1); rc=$?
    line=$(echo "$out" | grep -E '^([A-Za-z0-9_-]+: )?[0-9]+ passed, [0-9]+ failed' | tail -n 1)
    p=$(echo "$line" | sed -nE 's/^([A-Za-z0-9_-]+: )?([0-9]+) passed, ([0-9]+) failed.*/\2/p')
    f=$(echo "$line" | sed -nE 's/^([A-Za-z0-9_-]+: )?([0-9]+) passed, ([0-9]+) failed.*/\3/p')
    if [ -z "$p" ]; then
        echo "FAIL $label: no result (exit $rc)"; echo "$out" | tail -n 20; F=$((F + 1)); return
    fi
    [ "$rc" -ne 0 ] && [ "$f" -eq 0 ] && f=1
    [ "$f" -ne 0 ] && echo "$out" | grep -E '^(FAIL|  )' | head -n 30
    echo "$label: $p passed, $f failed"
    P=$((P + p)); F=$((F + f))
}
for spec in "rpi4 aarch64-linux-gnu- aarch64-linux-gnu qemu-aarch64-static -ffreestanding_-mgeneral-regs-only" \
            "rpi3-32 arm-linux-gnueabihf- arm-linux-gnueabihf qemu-arm-static -ffreestanding_-mfloat-abi=soft" \
            "rpi-zero arm-linux-gnueabi- arm-linux-gnueabi qemu-arm-static_-cpu_arm1176 -ffreestanding_-mfloat-abi=soft_-march=armv6_-marm"; do
    set -- $spec
    board=$1; cross=$2; triplet=$3; qemu=$(echo "$4" | tr _ ' '); fsflags=$(echo "$5" | tr _ ' ')
    case " ${ARM_BOARDS:-$board} " in *" $board "*) ;; *) continue ;; esac
    qbin=${qemu%% *}
    why=""
    command -v "${cross}gcc" >/dev/null 2>&1 || why="no ${cross}gcc"
    [ -z "$why" ] && ! command -v "$qbin" >/dev/null 2>&1 && why="no $qbin"
    if [ -n "$why" ]; then
        echo "SKIP $board: $why (run tests/arm/deps.sh as root)"
        continue
    fi
    echo "== $board ($triplet, $qemu)"
    if ! make --no-print-directory -j2 BOARD=$board STATIC=1 test-bins > "build/test-arm-$board.log" 2>&1; then
        echo "FAIL $board: build failed; see build/test-arm-$board.log"; tail -n 15 "build/test-arm-$board.log"
        F=$((F + 1)); continue
    fi
    skipped=$(make --no-print-directory -s BOARD=$board STATIC=1 print-TEST_NEEDS_128 2>/dev/null)
    [ -n "$skipped" ] && echo "   (no __int128 on $triplet: not built here, run on 64-bit hosts: $skipped)"
    # ARM_NO_UNIT="rpi-zero ...": those boards' unit run is left out (make
    # test's: armel's unit suite is the armhf one again with soft-float
    # doubles in its references, 330 s of CPU under qemu; make test-arm
    # runs it). Their golden, GLUT and integer-only runs stay.
    case " ${ARM_NO_UNIT:-} " in
    *" $board "*) echo "   (unit: left out here, ARM_NO_UNIT; make test-arm runs it)" ;;
    *) run_suite "$board unit" $qemu build/$board/static/tests/unit ;;
    esac
    # The board profile's own pkg-config query (for rpi-zero the armel
    # sysroot when the multiarch packages are absent: tests/arm/sysroot-armel.sh).
    have_png=$(make --no-print-directory -s BOARD=$board STATIC=1 print-HAVE_PNG)
    have_opt=$(make --no-print-directory -s BOARD=$board STATIC=1 print-HAVE_OPT)
    [ "$have_opt" = 1 ] ||
        echo "   (no libdrm/libevdev/libgpiod for $triplet: test_display, test_pointer and the tools not built;" \
             "run tests/arm/deps.sh as root$([ $board = rpi-zero ] && echo ", or sh tests/arm/sysroot-armel.sh"))"
    if [ "$have_png" = 1 ]; then
        run_suite "$board golden" $qemu build/$board/static/tests/golden --dir tests/golden --out build/$board/golden
    else
        # No target libpng: the target renders PPMs, the host compares them
        # with the same golden PNGs.
        echo "   (no libpng for $triplet: rendering PPMs on the target, comparing on the host)"
        rm -rf "build/$board/golden-ppm"
        [ -x build/tests/golden ] || make --no-print-directory -j2 test-bins > /dev/null 2>&1
        # the scripts' texture images, as PPM copies the target can read
        build/tests/golden --dir tests/golden --export-textures "build/$board/golden-ppm/textures"
        run_suite "$board golden render" $qemu build/$board/static/tests/golden --dir tests/golden --render-ppm build/$board/golden-ppm \
            --textures-ppm "build/$board/golden-ppm/textures"
        run_suite "$board golden" build/tests/golden --dir tests/golden --out build/$board/golden --compare-ppm build/$board/golden-ppm
    fi
    # The GLUT layer's course programs: the same frames as on x86-64.
    run_suite "$board glut frames" sh tests/arm/glut-frames.sh "$board" "$cross" $qemu
    FX_FS_FLAGS="$fsflags" run_suite "$board integer-only core" \
        sh tests/check-freestanding.sh "${cross}gcc" "${cross}nm" "build/$board/freestanding" $(make --no-print-directory -s print-CORE_SRC)
done
echo "test-arm$(echo ${ARM_BOARDS:+-$ARM_BOARDS} | tr " " -): $P passed, $F failed"
[ $F -eq 0 ]
