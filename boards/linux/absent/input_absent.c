/* SPDX-License-Identifier: MIT */
/* Built instead of boards/linux/input/ when libevdev and libgpiod are not
 * there: no input devices and no GPIO lines, said once. */
#include <stdint.h>

#include "../input/input_int.h"
#include "fixel/error.h"

void fx_evdev_scan(fx_evdev_set *s)
{
    fx_log(&s->log, FX_LOG_INFO, "input: this build has no libevdev; no input devices (install libevdev-dev and rebuild fixel)");
}
int fx_evdev_open(fx_evdev_set *s, const char *path, int quiet) { (void)s, (void)path, (void)quiet; return -FX_ENOTSUP; }
void fx_evdev_read(fx_evdev_set *s, int index) { (void)s, (void)index; }
void fx_evdev_hotplug(fx_evdev_set *s) { (void)s; }
void fx_evdev_close_all(fx_evdev_set *s) { (void)s; }

int fx_gpio_open_buttons(fx_gpio_set *s, const fx_gpio_button *b, int n)
{
    (void)b;
    if (n > 0)
        fx_log(&s->log, FX_LOG_ERROR, "gpio: this build has no libgpiod; buttons ignored (install libgpiod-dev and rebuild fixel)");
    return 0;
}
void fx_gpio_read(fx_gpio_set *s, int index) { (void)s, (void)index; }
uint64_t fx_gpio_poll(fx_gpio_set *s, uint64_t now) { (void)s, (void)now; return UINT64_MAX; }
void fx_gpio_close_all(fx_gpio_set *s) { (void)s; }
int fx_gpio_output(fx_gpio_set *s, const char *chip, int offset, int value)
{
    (void)s, (void)chip, (void)offset, (void)value;
    return -FX_ENOTSUP;
}
