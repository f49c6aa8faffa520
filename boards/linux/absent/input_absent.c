/* Built instead of boards/linux/input/ when libevdev and libgpiod are not
 * there: an app has no input devices and no GPIO lines, and says so once. */
#include <stdint.h>

#include "../../app/app_int.h"
#include "fixel/error.h"

void fx_evdev_scan(fx_app *a)
{
    fx_display_log(a->disp, FX_LOG_INFO, "input: this build has no libevdev; no input devices");
}
int fx_evdev_open(fx_app *a, const char *path, int quiet) { (void)a, (void)path, (void)quiet; return -FX_ENOTSUP; }
void fx_evdev_read(fx_app *a, int index) { (void)a, (void)index; }
void fx_evdev_hotplug(fx_app *a) { (void)a; }
void fx_evdev_close_all(fx_app *a) { (void)a; }

int fx_gpio_open_buttons(fx_app *a, const fx_gpio_button *b, int n)
{
    (void)b;
    if (n > 0)
        fx_display_log(a->disp, FX_LOG_ERROR, "gpio: this build has no libgpiod; buttons ignored");
    return 0;
}
void fx_gpio_read(fx_app *a, int index) { (void)a, (void)index; }
uint64_t fx_gpio_poll(fx_app *a, uint64_t now) { (void)a, (void)now; return UINT64_MAX; }
void fx_gpio_close_all(fx_app *a) { (void)a; }
int fx_app_gpio_output(fx_app *a, const char *chip, int offset, int value)
{
    (void)a, (void)chip, (void)offset, (void)value;
    return -FX_ENOTSUP;
}
