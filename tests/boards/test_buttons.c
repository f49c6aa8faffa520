/* SPDX-License-Identifier: MIT */
/* The GPIO button map of boards/linux/buttons.c (FIXEL_GPIO_BUTTONS and a
 * board's BOARD_GPIO_BUTTONS use this syntax); the debouncer it feeds is
 * core and tested in tests/core/test_input.c. */
#include <string.h>

#include "fixel/app.h"
#include "fx_test.h"

FX_TEST(gpio_button_spec_parsing)
{
    char spec[] = "gpiochip0:17=up,gpiochip0:BUTTON_A=a/low@50,1:4=f5,gpiochip2:3=enter";
    fx_gpio_button b[8];
    FX_CHECK_EQ(fx_gpio_parse_buttons(spec, b, 8), 4);
    FX_CHECK(!strcmp(b[0].chip, "gpiochip0") && b[0].offset == 17 && b[0].special && b[0].key == FX_KEY_UP);
    FX_CHECK(b[1].offset == -1 && !strcmp(b[1].name, "BUTTON_A") && b[1].active_low &&
             b[1].debounce_ms == 50 && b[1].key == 'a' && !b[1].special);
    FX_CHECK(!strcmp(b[2].chip, "1") && b[2].offset == 4 && b[2].special && b[2].key == FX_KEY_F5);
    FX_CHECK(b[3].key == 13 && !b[3].special);
    char bad1[] = "gpiochip0=up", bad2[] = "c:1=nosuchkey", bad3[] = "c:1=f13", bad4[] = "c:1=a@x";
    FX_CHECK(fx_gpio_parse_buttons(bad1, b, 8) < 0);
    FX_CHECK(fx_gpio_parse_buttons(bad2, b, 8) < 0);
    FX_CHECK(fx_gpio_parse_buttons(bad3, b, 8) < 0);
    FX_CHECK(fx_gpio_parse_buttons(bad4, b, 8) < 0);
    char anychip[] = ":GPIO17=up/low";
    FX_CHECK_EQ(fx_gpio_parse_buttons(anychip, b, 8), 1);
    FX_CHECK(b[0].chip == NULL && !strcmp(b[0].name, "GPIO17") && b[0].active_low);
    char menu[] = "c:5=menu"; /* opens a GLUT program's pop-up menu */
    FX_CHECK_EQ(fx_gpio_parse_buttons(menu, b, 8), 1);
    FX_CHECK(b[0].special && b[0].key == FX_KEY_MENU);
    char many[] = "c:1=a,c:2=b,c:3=c";
    FX_CHECK(fx_gpio_parse_buttons(many, b, 2) < 0);
}
