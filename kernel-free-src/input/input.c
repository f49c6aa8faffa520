/* SPDX-License-Identifier: MIT */
/* fixel — raw input to events (see fixel/input.h). */
#include "fixel/input.h"
#include "fixel/error.h"
#include "fixel/fixed.h"
#include "../base/fx_internal.h"

void fx_input_init(fx_input *in, int32_t phys_w, int32_t phys_h, int rotation)
{
    fx_memset(in, 0, sizeof *in);
    in->phys_w = phys_w > 0 ? phys_w : 1;
    in->phys_h = phys_h > 0 ? phys_h : 1;
    in->rotation = rotation == 90 || rotation == 180 || rotation == 270 ? rotation : 0;
    in->px = in->phys_w / 2;
    in->py = in->phys_h / 2;
}

void fx_input_dev_init(fx_input_dev *d, unsigned cls)
{
    fx_memset(d, 0, sizeof *d);
    d->cls = cls;
    for (int i = 0; i < 2; i++) {
        d->abs_min[i] = d->mt_min[i] = 0;
        d->abs_max[i] = d->mt_max[i] = -1; /* unknown: use the screen size */
    }
    for (int i = 0; i < FX_INPUT_MAX_SLOTS; i++)
        d->slots[i].id = -1;
}

void fx_input_logical_size(const fx_input *in, int32_t *w, int32_t *h)
{
    int swap = in->rotation == 90 || in->rotation == 270;
    *w = swap ? in->phys_h : in->phys_w;
    *h = swap ? in->phys_w : in->phys_h;
}

/* The display shows the logical picture turned clockwise by the rotation,
 * so a physical pixel maps back by turning counter-clockwise. */
void fx_input_to_logical(const fx_input *in, int32_t px, int32_t py, int32_t *lx, int32_t *ly)
{
    switch (in->rotation) {
    case 90: *lx = py; *ly = in->phys_w - 1 - px; break;
    case 180: *lx = in->phys_w - 1 - px; *ly = in->phys_h - 1 - py; break;
    case 270: *lx = in->phys_h - 1 - py; *ly = px; break;
    default: *lx = px; *ly = py; break;
    }
}

static int32_t clamp(int64_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : v > hi ? hi : (int32_t)v;
}

/* a + b saturated to [-INT64_MAX, INT64_MAX]: three pointercal terms of up
 * to 2^62 each do not fit 64 bits, and a saturated sum divided by a
 * coefficient of at most 2^31 still lands far outside the screen, where the
 * clamp puts it, so saturating loses nothing. */
static int64_t sat_add(int64_t a, int64_t b)
{
    if (b > 0 && a > INT64_MAX - b)
        return INT64_MAX;
    if (b < 0 && a < -INT64_MAX - b)
        return -INT64_MAX;
    return a + b;
}

/* r in [lo, hi] (any int32 range, hi - lo up to 2^32 - 1) scaled to
 * 0..n-1, rounded to nearest so the range ends land on the edge pixels.
 * Out-of-range r is clamped first (the result would be clamped anyway), so
 * the numerator is at most (2^32 - 1)(2^31 - 2) < 2^63; the rounding is
 * floor((2A + d) / 2d) computed as q + (2r >= d) without forming 2A. */
static int64_t scale_range(int32_t r, int32_t lo, int32_t hi, int32_t n)
{
    int64_t d = (int64_t)hi - lo, t = (int64_t)r - lo;
    t = t < 0 ? 0 : t > d ? d : t;
    int64_t a = t * (n - 1), q = a / d, rem = a % d;
    return q + (2 * rem >= d);
}

/* Device units -> physical screen pixels, by calibration or range scaling.
 * Any int32 device values, ranges and coefficients give a pixel on the
 * screen: the arithmetic is 64-bit and every step is bounded (issue #40). */
static void to_screen(const fx_input *in, const fx_input_dev *d, int32_t rx, int32_t ry,
                      const int32_t *mn, const int32_t *mx, int32_t *sx, int32_t *sy)
{
    const fx_calib *c = &d->calib;
    int64_t x, y;
    int32_t W = in->phys_w, H = in->phys_h;
    if (c->valid && c->a[6] != 0) {
        /* each product is at most 2^62 in size; the sums saturate */
        x = sat_add(sat_add(c->a[2], (int64_t)c->a[0] * rx), (int64_t)c->a[1] * ry) / c->a[6];
        y = sat_add(sat_add(c->a[5], (int64_t)c->a[3] * rx), (int64_t)c->a[4] * ry) / c->a[6];
    } else {
        int32_t x0 = mn[0], x1 = mx[0], y0 = mn[1], y1 = mx[1];
        if (c->xmin < c->xmax)
            x0 = c->xmin, x1 = c->xmax;
        if (c->ymin < c->ymax)
            y0 = c->ymin, y1 = c->ymax;
        if (c->swap_xy) { /* the ranges belong to the panel's axes after swapping */
            int32_t t = rx;
            rx = ry;
            ry = t;
            t = x0, x0 = y0, y0 = t;
            t = x1, x1 = y1, y1 = t;
        }
        if (x1 <= x0)
            x0 = 0, x1 = W - 1;
        if (y1 <= y0)
            y0 = 0, y1 = H - 1;
        x = x1 > x0 ? scale_range(rx, x0, x1, W) : 0; /* W == 1: one column */
        y = y1 > y0 ? scale_range(ry, y0, y1, H) : 0;
        if (c->invert_x)
            x = W - 1 - x;
        if (c->invert_y)
            y = H - 1 - y;
        *sx = clamp(x, 0, W - 1);
        *sy = clamp(y, 0, H - 1);
        return;
    }
    if (c->swap_xy) {
        int64_t t = x;
        x = y;
        y = t;
    }
    /* clamped before the flip: W - 1 - x must not overflow */
    x = clamp(x, 0, W - 1);
    y = clamp(y, 0, H - 1);
    if (c->invert_x)
        x = W - 1 - x;
    if (c->invert_y)
        y = H - 1 - y;
    *sx = (int32_t)x;
    *sy = (int32_t)y;
}

static void emit_at(const fx_input *in, fx_event *e, fx_emit_fn emit, void *user)
{
    fx_input_to_logical(in, in->px, in->py, &e->x, &e->y);
    e->mods = in->mods;
    emit(user, e);
}

static void update_mods(fx_input *in)
{
    in->mods = (in->shift_l || in->shift_r ? FX_MOD_SHIFT : 0u) |
               (in->ctrl_l || in->ctrl_r ? FX_MOD_CTRL : 0u) | (in->alt_l || in->alt_r ? FX_MOD_ALT : 0u);
}

static void key_event(fx_input *in, unsigned code, int32_t value, uint64_t t, fx_emit_fn emit,
                      void *user)
{
    int down = value != 0;
    switch (code) {
    case 42: in->shift_l = (uint8_t)down; update_mods(in); return;
    case 54: in->shift_r = (uint8_t)down; update_mods(in); return;
    case 29: in->ctrl_l = (uint8_t)down; update_mods(in); return;
    case 97: in->ctrl_r = (uint8_t)down; update_mods(in); return;
    case 56: in->alt_l = (uint8_t)down; update_mods(in); return;
    case 100: in->alt_r = (uint8_t)down; update_mods(in); return;
    case 58:
        if (value == 1)
            in->caps ^= 1;
        return;
    default: break;
    }
    int k = fx_keymap_us(code, in->mods, in->caps);
    if (!k)
        return;
    fx_event e;
    fx_memset(&e, 0, sizeof e);
    e.time_us = t;
    if (k > 0) {
        e.type = down ? FX_EVENT_KEY : FX_EVENT_KEY_UP;
        e.key = k;
    } else {
        e.type = down ? FX_EVENT_SPECIAL : FX_EVENT_SPECIAL_UP;
        e.key = -k;
    }
    emit_at(in, &e, emit, user);
}

/* bit of btn_state: 0 left, 1 right, 2 middle, 3 touch/pen tip */
static int button_bit(unsigned code)
{
    switch (code) {
    case FX_IN_BTN_LEFT: return 0;
    case FX_IN_BTN_RIGHT:
    case FX_IN_BTN_STYLUS: return 1;
    case FX_IN_BTN_MIDDLE: return 2;
    case FX_IN_BTN_TOUCH: return 3;
    default: return -1;
    }
}

static void frame(fx_input *in, fx_input_dev *d, uint64_t t, fx_emit_fn emit, void *user)
{
    fx_event e;
    fx_memset(&e, 0, sizeof e);
    e.time_us = t;
    /* 1. pointer motion, reported as motion or passive by the buttons held
     *    before this frame's button changes (as GLUT does) */
    int moved = 0;
    if (d->rel[0] || d->rel[1]) {
        /* A mouse moves the pointer across the picture the user looks at
         * (logical), however the panel is mounted: turn the step into
         * physical pixels. 64-bit so negating a saturated step is defined. */
        int64_t dx = d->rel[0], dy = d->rel[1], pdx, pdy;
        switch (in->rotation) {
        case 90: pdx = -dy; pdy = dx; break;
        case 180: pdx = -dx; pdy = -dy; break;
        case 270: pdx = dy; pdy = -dx; break;
        default: pdx = dx; pdy = dy; break;
        }
        int32_t nx = clamp((int64_t)in->px + pdx, 0, in->phys_w - 1);
        int32_t ny = clamp((int64_t)in->py + pdy, 0, in->phys_h - 1);
        moved = nx != in->px || ny != in->py;
        in->px = nx;
        in->py = ny;
    }
    if (d->abs_dirty) {
        int32_t sx, sy;
        to_screen(in, d, d->abs[0], d->abs[1], d->abs_min, d->abs_max, &sx, &sy);
        moved |= sx != in->px || sy != in->py;
        in->px = sx;
        in->py = sy;
    }
    /* Multitouch devices without the legacy ABS_X/ABS_Y axes drive the
     * pointer from slot 0. */
    if ((d->cls & FX_DEV_MT) && d->abs_max[0] < 0 && d->slots[0].dirty && d->slots[0].active) {
        int32_t sx, sy;
        to_screen(in, d, d->slots[0].x, d->slots[0].y, d->mt_min, d->mt_max, &sx, &sy);
        moved |= sx != in->px || sy != in->py;
        in->px = sx;
        in->py = sy;
    }
    if (moved) {
        e.type = in->buttons ? FX_EVENT_MOTION : FX_EVENT_PASSIVE;
        emit_at(in, &e, emit, user);
    }
    /* 2. buttons; the touch/pen tip acts as the left button */
    for (int bit = 0; bit < 4; bit++) {
        if (!(d->btn_changed & (1u << bit)))
            continue;
        int down = (d->btn_state >> bit) & 1;
        int button = bit == 1 ? FX_BUTTON_RIGHT : bit == 2 ? FX_BUTTON_MIDDLE : FX_BUTTON_LEFT;
        unsigned mask = 1u << button;
        if (down == !!(in->buttons & mask))
            continue; /* e.g. BTN_TOUCH and BTN_LEFT both held */
        in->buttons = down ? in->buttons | mask : in->buttons & ~mask;
        e.type = FX_EVENT_MOUSE;
        e.button = (uint8_t)button;
        e.state = down ? FX_DOWN : FX_UP;
        emit_at(in, &e, emit, user);
    }
    e.button = e.state = 0;
    /* 3. wheel */
    if (d->wheel) {
        e.type = FX_EVENT_WHEEL;
        e.value = d->wheel > 0 ? 1 : -1;
        emit_at(in, &e, emit, user);
        e.value = 0;
    }
    /* 4. multitouch contacts */
    for (int s = 0; s < FX_INPUT_MAX_SLOTS; s++) {
        if (!d->slots[s].dirty)
            continue;
        int32_t sx, sy;
        to_screen(in, d, d->slots[s].x, d->slots[s].y, d->mt_min, d->mt_max, &sx, &sy);
        fx_input_to_logical(in, sx, sy, &e.x, &e.y);
        e.type = FX_EVENT_TOUCH;
        e.id = s;
        e.mods = in->mods;
        if (d->slots[s].active && !d->slots[s].was_active)
            e.phase = FX_TOUCH_DOWN;
        else if (!d->slots[s].active && d->slots[s].was_active)
            e.phase = FX_TOUCH_UP;
        else if (d->slots[s].active)
            e.phase = FX_TOUCH_MOVE;
        else
            goto clean;
        emit(user, &e);
    clean:
        d->slots[s].was_active = d->slots[s].active;
        d->slots[s].dirty = 0;
    }
    d->rel[0] = d->rel[1] = d->wheel = 0;
    d->abs_dirty = 0;
    d->btn_changed = 0;
}

void fx_input_feed(fx_input *in, fx_input_dev *d, const fx_raw_event *ev, fx_emit_fn emit, void *user)
{
    if (ev->type == FX_IN_SYN) {
        if (ev->code == FX_IN_SYN_DROPPED) {
            /* The kernel's buffer overflowed: what was collected is
             * incomplete; drop it and wait for the resynchronised state. */
            d->dropped = 1;
            d->rel[0] = d->rel[1] = d->wheel = 0;
            d->abs_dirty = 0;
            d->btn_changed = 0;
            return;
        }
        if (ev->code == FX_IN_SYN_REPORT) {
            if (d->dropped) {
                d->dropped = 0;
                return;
            }
            frame(in, d, ev->time_us, emit, user);
        }
        return;
    }
    if (d->dropped)
        return;
    switch (ev->type) {
    case FX_IN_KEY: {
        int bit = button_bit(ev->code);
        if (bit >= 0) {
            if (ev->value == 2)
                break;
            uint16_t m = (uint16_t)(1u << bit);
            d->btn_changed |= m;
            d->btn_state = ev->value ? d->btn_state | m : d->btn_state & (uint16_t)~m;
        } else if (ev->code < 0x100) {
            key_event(in, ev->code, ev->value, ev->time_us, emit, user);
        }
        break;
    }
    case FX_IN_REL:
        if (ev->code == FX_IN_REL_X)
            d->rel[0] = fx_sat32((int64_t)d->rel[0] + ev->value);
        else if (ev->code == FX_IN_REL_Y)
            d->rel[1] = fx_sat32((int64_t)d->rel[1] + ev->value);
        else if (ev->code == FX_IN_REL_WHEEL)
            d->wheel = fx_sat32((int64_t)d->wheel + ev->value);
        break;
    case FX_IN_ABS:
        if (ev->code == FX_IN_ABS_X || ev->code == FX_IN_ABS_Y) {
            d->abs[ev->code] = ev->value;
            d->abs_dirty = 1;
        } else if (ev->code == FX_IN_ABS_MT_SLOT) {
            d->slot = ev->value;
        } else if (d->slot >= 0 && d->slot < FX_INPUT_MAX_SLOTS) {
            if (ev->code == FX_IN_ABS_MT_TRACKING_ID) {
                d->slots[d->slot].active = ev->value >= 0;
                d->slots[d->slot].id = ev->value;
                d->slots[d->slot].dirty = 1;
            } else if (ev->code == FX_IN_ABS_MT_POSITION_X) {
                d->slots[d->slot].x = ev->value;
                d->slots[d->slot].dirty = 1;
            } else if (ev->code == FX_IN_ABS_MT_POSITION_Y) {
                d->slots[d->slot].y = ev->value;
                d->slots[d->slot].dirty = 1;
            }
        }
        break;
    default: break;
    }
}

int fx_calib_parse(fx_calib *c, const char *text, unsigned len)
{
    int64_t v[7];
    int n = 0;
    unsigned i = 0;
    while (n < 7) {
        while (i < len && (text[i] == ' ' || text[i] == '\t' || text[i] == '\n' || text[i] == '\r'))
            i++;
        if (i >= len)
            break;
        int neg = 0;
        if (text[i] == '-' || text[i] == '+')
            neg = text[i++] == '-';
        if (i >= len || text[i] < '0' || text[i] > '9')
            return -FX_EINVAL;
        int64_t acc = 0;
        while (i < len && text[i] >= '0' && text[i] <= '9') {
            acc = acc * 10 + (text[i++] - '0');
            if (acc > INT32_MAX)
                return -FX_EINVAL;
        }
        v[n++] = neg ? -acc : acc;
    }
    if (n < 7 || v[6] == 0)
        return -FX_EINVAL;
    for (int k = 0; k < 7; k++)
        c->a[k] = (int32_t)v[k];
    c->valid = 1;
    return 0;
}

/* US layout for evdev key codes 0..58: unshifted and shifted characters. */
static const char us_lower[59] = {
    0,   27,  '1', '2', '3', '4', '5', '6', '7', '8', '9', '0', '-', '=', 8,   9,
    'q', 'w', 'e', 'r', 't', 'y', 'u', 'i', 'o', 'p', '[', ']', 13,  0,   'a', 's',
    'd', 'f', 'g', 'h', 'j', 'k', 'l', ';', '\'', '`', 0,  '\\', 'z', 'x', 'c', 'v',
    'b', 'n', 'm', ',', '.', '/', 0,   '*', 0,   ' ', 0};
static const char us_upper[59] = {
    0,   27,  '!', '@', '#', '$', '%', '^', '&', '*', '(', ')', '_', '+', 8,   9,
    'Q', 'W', 'E', 'R', 'T', 'Y', 'U', 'I', 'O', 'P', '{', '}', 13,  0,   'A', 'S',
    'D', 'F', 'G', 'H', 'J', 'K', 'L', ':', '"', '~', 0,   '|', 'Z', 'X', 'C', 'V',
    'B', 'N', 'M', '<', '>', '?', 0,   '*', 0,   ' ', 0};

int fx_keymap_us(unsigned code, unsigned mods, int caps)
{
    if (code >= 59 && code <= 68)
        return -(FX_KEY_F1 + (int)(code - 59));
    switch (code) {
    case 87: return -FX_KEY_F11;
    case 88: return -FX_KEY_F12;
    case 102: return -FX_KEY_HOME;
    case 103: return -FX_KEY_UP;
    case 104: return -FX_KEY_PAGE_UP;
    case 105: return -FX_KEY_LEFT;
    case 106: return -FX_KEY_RIGHT;
    case 107: return -FX_KEY_END;
    case 108: return -FX_KEY_DOWN;
    case 109: return -FX_KEY_PAGE_DOWN;
    case 110: return -FX_KEY_INSERT;
    case 111: return 127; /* Delete, as GLUT reports it */
    case 127:             /* KEY_COMPOSE: the Menu key beside the right Ctrl */
    case 139: return -FX_KEY_MENU; /* KEY_MENU */
    case 96: return 13;   /* keypad Enter */
    case 98: return '/';
    case 74: return '-';
    case 78: return '+';
    default: break;
    }
    if (code >= 71 && code <= 83) { /* keypad digits (Num Lock assumed on) */
        static const char kp[] = "789-456+1230.";
        return kp[code - 71];
    }
    if (code >= 59)
        return 0;
    char lo = us_lower[code], up = us_upper[code];
    if (!lo)
        return 0;
    int letter = lo >= 'a' && lo <= 'z';
    int shift = (mods & FX_MOD_SHIFT) != 0;
    if (letter && caps)
        shift = !shift;
    char ch = shift ? up : lo;
    if ((mods & FX_MOD_CTRL) && letter)
        return lo - 'a' + 1; /* Ctrl-A = 1 ... Ctrl-Z = 26 */
    return (unsigned char)ch;
}

void fx_debounce_init(fx_debounce *d, uint32_t ms, int level)
{
    d->ms = ms;
    d->stable = d->raw = (uint8_t)(level != 0);
    d->last_us = 0;
}

void fx_debounce_edge(fx_debounce *d, int level, uint64_t t_us)
{
    d->raw = (uint8_t)(level != 0);
    d->last_us = t_us;
}

int fx_debounce_poll(fx_debounce *d, uint64_t now_us)
{
    if (d->raw == d->stable || now_us < d->last_us + (uint64_t)d->ms * 1000)
        return -1;
    d->stable = d->raw;
    return d->stable;
}

uint64_t fx_debounce_deadline(const fx_debounce *d)
{
    return d->raw == d->stable ? UINT64_MAX : d->last_us + (uint64_t)d->ms * 1000;
}
