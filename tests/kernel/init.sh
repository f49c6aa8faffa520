#!/bin/busybox sh
# SPDX-License-Identifier: MIT
# /init of the rig's guest: mount the kernel filesystems, load the modules,
# run every test program in /tests, power off. Markers on the serial console
# (RIG ...) tell the host where the run is; see README.md.
/bin/busybox --install -s /bin
export PATH=/bin
# The virtio tablet would turn the software pointer on in every program
# whose screen is compared; guest/pointer.c asks for it where it checks it.
export FIXEL_POINTER=off
mount -t proc proc /proc
mount -t sysfs sys /sys
mount -t devtmpfs dev /dev
mkdir -p /dev/pts && mount -t devpts devpts /dev/pts
while read -r m; do
    insmod "/lib/modules/$m" || echo "RIG MODULE-FAILED $m"
done < /modules.load
mount -t configfs configfs /sys/kernel/config
# The DRM driver registers its fbdev emulation right after probe; wait for both.
i=0
while [ $i -lt 50 ] && ! { [ -e /dev/dri/card0 ] && [ -e /dev/fb0 ]; }; do
    sleep 0.1; i=$((i + 1))
done
chgrp video /dev/dri/card* /dev/fb* 2>/dev/null
chmod 660 /dev/dri/card* /dev/fb* 2>/dev/null
chgrp input /dev/input/* /dev/uinput 2>/dev/null
chmod 660 /dev/input/event* /dev/uinput 2>/dev/null
# Stands in for a shell on the console VT: whatever the keyboard delivers to
# tty1 ends up here, so tests can show it received (or not) keystrokes.
cat /dev/tty1 > /tmp/tty1.log 2>/dev/null &
stty -echo 2>/dev/null
echo "RIG BOOTED $(uname -r) $(uname -m)"
for t in /tests/*; do
    [ -x "$t" ] || continue
    n=${t##*/}
    echo "RIG RUN $n"
    "$t"
    echo "RIG EXIT $n $?"
done
echo "RIG DONE"
poweroff -f
