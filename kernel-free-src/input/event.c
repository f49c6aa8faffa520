/* SPDX-License-Identifier: MIT */
/* fixel — GLUT-style dispatch of fx_event. */
#include "fixel/event.h"
#include "fixel/draw.h"

void fx_dispatch(const fx_callbacks *cb, void *u, const fx_event *e)
{
    switch (e->type) {
    case FX_EVENT_KEY:
        if (cb->keyboard)
            cb->keyboard(u, (unsigned char)e->key, e->x, e->y);
        break;
    case FX_EVENT_KEY_UP:
        if (cb->keyboard_up)
            cb->keyboard_up(u, (unsigned char)e->key, e->x, e->y);
        break;
    case FX_EVENT_SPECIAL:
        if (cb->special)
            cb->special(u, e->key, e->x, e->y);
        break;
    case FX_EVENT_SPECIAL_UP:
        if (cb->special_up)
            cb->special_up(u, e->key, e->x, e->y);
        break;
    case FX_EVENT_MOUSE:
        if (cb->mouse)
            cb->mouse(u, e->button, e->state, e->x, e->y);
        break;
    case FX_EVENT_MOTION:
        if (cb->motion)
            cb->motion(u, e->x, e->y);
        break;
    case FX_EVENT_PASSIVE:
        if (cb->passive_motion)
            cb->passive_motion(u, e->x, e->y);
        break;
    case FX_EVENT_WHEEL:
        if (cb->wheel)
            cb->wheel(u, e->value, e->x, e->y);
        break;
    case FX_EVENT_TOUCH:
        if (cb->touch)
            cb->touch(u, e->id, e->x, e->y, e->phase);
        break;
    case FX_EVENT_RESHAPE:
        if (cb->reshape)
            cb->reshape(u, e->x, e->y);
        break;
    case FX_EVENT_CLOSE:
        if (cb->close)
            cb->close(u);
        break;
    default: break;
    }
}

static const char *const button_names[] = {"left", "middle", "right"};
static const char *const phase_names[] = {"down", "move", "up"};

int fx_event_describe(const fx_event *e, char *buf, unsigned size)
{
    switch (e->type) {
    case FX_EVENT_KEY:
    case FX_EVENT_KEY_UP:
        return fx_fmt(buf, size, "%s %d %d %d", e->type == FX_EVENT_KEY ? "key" : "keyup",
                      (int)e->key, (int)e->x, (int)e->y);
    case FX_EVENT_SPECIAL:
    case FX_EVENT_SPECIAL_UP:
        return fx_fmt(buf, size, "%s %d %d %d", e->type == FX_EVENT_SPECIAL ? "special" : "specialup",
                      (int)e->key, (int)e->x, (int)e->y);
    case FX_EVENT_MOUSE:
        return fx_fmt(buf, size, "mouse %s %s %d %d", e->button < 3 ? button_names[e->button] : "?",
                      e->state == FX_DOWN ? "down" : "up", (int)e->x, (int)e->y);
    case FX_EVENT_MOTION: return fx_fmt(buf, size, "motion %d %d", (int)e->x, (int)e->y);
    case FX_EVENT_PASSIVE: return fx_fmt(buf, size, "passive %d %d", (int)e->x, (int)e->y);
    case FX_EVENT_WHEEL:
        return fx_fmt(buf, size, "wheel %d %d %d", (int)e->value, (int)e->x, (int)e->y);
    case FX_EVENT_TOUCH:
        return fx_fmt(buf, size, "touch %d %s %d %d", (int)e->id,
                      e->phase < 3 ? phase_names[e->phase] : "?", (int)e->x, (int)e->y);
    case FX_EVENT_RESHAPE: return fx_fmt(buf, size, "reshape %d %d", (int)e->x, (int)e->y);
    case FX_EVENT_CLOSE: return fx_fmt(buf, size, "close");
    default: return fx_fmt(buf, size, "none");
    }
}
