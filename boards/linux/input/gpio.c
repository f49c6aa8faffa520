/* SPDX-License-Identifier: MIT */
/* fixel — GPIO buttons and output lines through libgpiod (v1.6 API). */
#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <errno.h>
#include <gpiod.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixel/error.h"
#include "input_int.h"

static int open_line(fx_gpio_set *a, const char *chipname, int offset, const char *name,
                     struct gpiod_chip **chip, struct gpiod_line **line, int *close_chip)
{
    *chip = NULL;
    *line = NULL;
    *close_chip = 0;
    if (chipname) {
        *chip = gpiod_chip_open_lookup(chipname);
        if (!*chip) {
            int e = errno;
            fx_log(&a->log, FX_LOG_ERROR, "gpio: cannot open chip %s: %s%s", chipname,
                           strerror(e), e == EACCES ? " (add the user to the 'gpio' group)" : "");
            return -e;
        }
        *line = offset >= 0 ? gpiod_chip_get_line(*chip, (unsigned)offset)
                            : gpiod_chip_find_line(*chip, name);
    } else if (name) {
        *line = gpiod_line_find(name);
        *close_chip = *line != NULL;
    }
    if (!*line) {
        if (name && offset < 0)
            fx_log(&a->log, FX_LOG_ERROR, "gpio: no line named \"%s\" on %s", name,
                           chipname ? chipname : "any chip");
        else
            fx_log(&a->log, FX_LOG_ERROR, "gpio: no line %d on %s", offset,
                           chipname ? chipname : "(no chip given)");
        if (*chip)
            gpiod_chip_close(*chip);
        *chip = NULL;
        return -FX_ENODEV;
    }
    return 0;
}

int fx_gpio_open_buttons(fx_gpio_set *a, const fx_gpio_button *b, int n)
{
    int opened = 0;
    for (int i = 0; i < n && a->nin < FX_GPIO_MAX_IN; i++) {
        fx_gpio_in *g = &a->in[a->nin];
        memset(g, 0, sizeof *g);
        if (open_line(a, b[i].chip, b[i].offset, b[i].name, &g->chip, &g->line, &g->close_chip) < 0)
            continue;
        /* An active-low button shorts the line to ground: enable the pull-up
         * so an open button reads high instead of floating. */
        int flags = b[i].active_low
                        ? GPIOD_LINE_REQUEST_FLAG_ACTIVE_LOW | GPIOD_LINE_REQUEST_FLAG_BIAS_PULL_UP
                        : 0;
        if (gpiod_line_request_both_edges_events_flags(g->line, "fixel", flags) < 0) {
            int e = errno;
            fx_log(&a->log, FX_LOG_ERROR, "gpio: cannot request line %d: %s%s",
                           (int)gpiod_line_offset(g->line), strerror(e),
                           e == EBUSY ? " (another program uses it)" : "");
            if (g->close_chip)
                gpiod_line_close_chip(g->line);
            else
                gpiod_chip_close(g->chip);
            continue;
        }
        g->fd = gpiod_line_event_get_fd(g->line);
        g->b = b[i];
        int level = gpiod_line_get_value(g->line);
        fx_debounce_init(&g->db, b[i].debounce_ms ? b[i].debounce_ms : 20, level > 0);
        a->nin++;
        opened++;
        fx_log(&a->log, FX_LOG_INFO, "gpio: button on line %u (%s) -> %s %d",
                       gpiod_line_offset(g->line), gpiod_line_name(g->line) ? gpiod_line_name(g->line) : "unnamed",
                       b[i].special ? "special" : "key", b[i].key);
    }
    return opened;
}

static void close_in(fx_gpio_in *g)
{
    gpiod_line_release(g->line);
    if (g->close_chip)
        gpiod_line_close_chip(g->line);
    else
        gpiod_chip_close(g->chip);
}

void fx_gpio_read(fx_gpio_set *a, int i)
{
    fx_gpio_in *g = &a->in[i];
    struct gpiod_line_event ev;
    /* The event fd blocks: poll() announced one event, read exactly one. */
    if (gpiod_line_event_read_fd(g->fd, &ev) < 0) {
        /* A chip that goes away (unbound driver, removed expander) fails
         * every line at once: drop them all with one message instead of one
         * per line as each fd reports in. */
        int e = errno;
        char chip[32];
        struct gpiod_chip *c = gpiod_line_get_chip(g->line);
        snprintf(chip, sizeof chip, "%s", c && gpiod_chip_name(c) ? gpiod_chip_name(c) : "?");
        int dropped = 0;
        for (int k = a->nin - 1; k >= 0; k--) {
            struct gpiod_chip *ck = gpiod_line_get_chip(a->in[k].line);
            if (k != i && !(e == ENODEV && ck && gpiod_chip_name(ck) && !strcmp(gpiod_chip_name(ck), chip)))
                continue;
            close_in(&a->in[k]);
            a->in[k] = a->in[--a->nin];
            dropped++;
        }
        fx_log(&a->log, FX_LOG_ERROR, "gpio: %s vanished (%s); %d button%s dropped",
                       chip, strerror(e), dropped, dropped == 1 ? "" : "s");
        return;
    }
    /* Timed on our monotonic clock, not ev.ts: older kernels stamp v1 line
     * events with CLOCK_REALTIME, which must not meet timerfd deadlines. */
    fx_debounce_edge(&g->db, ev.event_type == GPIOD_LINE_EVENT_RISING_EDGE, a->clock.now_us(a->clock.user));
}

uint64_t fx_gpio_poll(fx_gpio_set *a, uint64_t now)
{
    uint64_t next = UINT64_MAX;
    for (int i = 0; i < a->nin; i++) {
        fx_gpio_in *g = &a->in[i];
        int r = fx_debounce_poll(&g->db, now);
        if (r >= 0) {
            fx_event e;
            memset(&e, 0, sizeof e);
            e.type = g->b.special ? (r ? FX_EVENT_SPECIAL : FX_EVENT_SPECIAL_UP)
                                  : (r ? FX_EVENT_KEY : FX_EVENT_KEY_UP);
            e.key = g->b.key;
            e.time_us = now;
            a->sink.fn(a->sink.user, &e);
        }
        uint64_t d = fx_debounce_deadline(&g->db);
        if (d < next)
            next = d;
    }
    return next;
}

void fx_gpio_close_all(fx_gpio_set *a)
{
    while (a->nin)
        close_in(&a->in[--a->nin]);
    while (a->nout) {
        fx_gpio_out *o = &a->out[--a->nout];
        gpiod_line_release(o->line);
        gpiod_chip_close(o->chip);
    }
}

int fx_gpio_output(fx_gpio_set *a, const char *chip, int offset, int value)
{
    for (int i = 0; i < a->nout; i++)
        if (a->out[i].offset == offset && !strcmp(a->out[i].chipname, chip))
            return gpiod_line_set_value(a->out[i].line, value) < 0 ? -errno : 0;
    if (a->nout == FX_GPIO_MAX_OUT)
        return -FX_ENOSPC;
    fx_gpio_out *o = &a->out[a->nout];
    int close_chip;
    int r = open_line(a, chip, offset, NULL, &o->chip, &o->line, &close_chip);
    if (r < 0)
        return r;
    if (gpiod_line_request_output(o->line, "fixel", value) < 0) {
        r = -errno;
        fx_log(&a->log, FX_LOG_ERROR, "gpio: cannot drive %s line %d: %s", chip, offset,
                       strerror(-r));
        gpiod_chip_close(o->chip);
        return r;
    }
    snprintf(o->chipname, sizeof o->chipname, "%s", chip);
    o->offset = offset;
    a->nout++;
    return 0;
}
