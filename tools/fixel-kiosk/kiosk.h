/* SPDX-License-Identifier: MIT */
/* fixel-kiosk — the pure half: config and data-line parsers and the
 * fixed-size model they fill. No I/O and no allocation here, so the unit
 * tests and the fuzz target feed it memory buffers directly. */
#ifndef FIXEL_KIOSK_H
#define FIXEL_KIOSK_H

#include "kiosk_power.h"
#include <stddef.h>
#include <stdint.h>

#define KIOSK_MAX_WIDGETS 32
#define KIOSK_MAX_SOURCES 32
#define KIOSK_NAME_MAX 32   /* source names, including the NUL */
#define KIOSK_TEXT_MAX 64   /* labels, units, text values, including the NUL */
#define KIOSK_HIST_MAX 256  /* ring buffer length per source */
#define KIOSK_LINE_MAX 1024 /* longer data lines are bad lines (a 16x16 heat map fits) */
#define KIOSK_HEAT_MAX 256  /* cells of one heat map source (cells=CxR, C*R <= this) */
#define KIOSK_HEAT_DIM 16   /* C, R <= this */
#define KIOSK_PATH_MAX 256  /* image paths, including the NUL */
#define KIOSK_CSV_MAX 32    /* columns of a CSV header */
#define KIOSK_CELL_NONE INT32_MIN /* a heat map cell no line has set yet */

typedef enum kiosk_type {
    KIOSK_NUMBER, KIOSK_GAUGE, KIOSK_BAR, KIOSK_SPARK, KIOSK_TEXT, KIOSK_CLOCK, KIOSK_HEAT, KIOSK_IMAGE,
    KIOSK_QR,     /* a QR code of the source's text (or text=) */
    KIOSK_BUTTON, /* kiosk_pages.h: no source; a tap publishes and/or turns the page */
    KIOSK_NTYPES
} kiosk_type;

/* What a source carries, fixed by the widgets that show it. */
typedef enum kiosk_kind {
    KIOSK_KIND_TEXT = 0, /* only text widgets: any printable value */
    KIOSK_KIND_NUMBER,   /* number gauge bar spark (text widgets may share it) */
    KIOSK_KIND_HEAT,     /* heat: a list of numbers, one per cell */
    KIOSK_KIND_IMAGE     /* image: a file path */
} kiosk_kind;

typedef struct kiosk_widget {
    kiosk_type type;
    int source;                /* index into sources, -1 for the clock */
    int col, row, w, h;        /* grid cells */
    int decimals;              /* 0..3 */
    int64_t min, max;          /* milli-units; min == max: automatic (spark) */
    uint32_t color;            /* 0xAARRGGBB accent */
    int cmap;                  /* heat: an fx_cmap */
    int smooth;                /* heat: bilinear between cell centres; image: bilinear scaling */
    char label[KIOSK_TEXT_MAX];
    char unit[KIOSK_TEXT_MAX];
    int screen;                /* index into kiosk_config.outputs; 0 without output sections */
    int line;                  /* where it was declared (the grid is checked after the whole file) */
    int page;                  /* the page it is on (kiosk_pages.h) */
    int button;                /* button widgets: index into pg.buttons; else -1 */
    char qrtext[KIOSK_TEXT_MAX]; /* qr: shown until the source sends a value */
    int qr_ecc;                /* qr: 0..3 for L M Q H */
    int qr_quiet;              /* qr: modules of quiet zone around the code */
} kiosk_widget;

typedef struct kiosk_source {
    char name[KIOSK_NAME_MAX];
    int64_t value;             /* milli-units */
    int has_value;
    char text[KIOSK_TEXT_MAX]; /* the raw value as received */
    int64_t last_ms;           /* time of the last update */
    int64_t hist[KIOSK_HIST_MAX];
    uint32_t head, count;      /* ring buffer: next slot, valid entries */
    uint32_t updates;
    kiosk_kind kind;
    int gw, gh;                /* heat: cells across and down */
    int32_t cells[KIOSK_HEAT_MAX]; /* heat: milli-units, row-major, KIOSK_CELL_NONE unset */
    char path[KIOSK_PATH_MAX]; /* image: the file shown */
    uint32_t path_gen;         /* image: bumped by every line naming a path (forces a reload) */
} kiosk_source;

/* MQTT (docs/kiosk.md, "MQTT"): the broker and the topics that feed
 * sources. Parsed here like every other directive (ranges in kiosk_keys);
 * the client itself is kiosk_mqtt.c, built only with libmosquitto. */
#define KIOSK_MQTT_SUBS 16
#define KIOSK_TOPIC_MAX 128 /* topic filters and the control prefix, including the NUL */
#define KIOSK_HOST_MAX 128
#define KIOSK_JPATH_MAX 64  /* a JSON path such as sensors.temp or values[2] */
#define KIOSK_JPATH_DEPTH 16 /* steps of one JSON path */

typedef struct kiosk_sub {
    char topic[KIOSK_TOPIC_MAX]; /* a filter: + and # wildcards */
    int qos;                     /* 0..2 */
    int source;                  /* -1: the payload is data lines, exactly as on stdin */
    char json[KIOSK_JPATH_MAX];  /* "": the payload itself is the value */
    int line, col;               /* where it was declared (errors found after the whole file) */
    char srcname[KIOSK_NAME_MAX];
} kiosk_sub;

typedef struct kiosk_mqtt_cfg {
    int enabled;                 /* an "mqtt" directive was given */
    char host[KIOSK_HOST_MAX];
    int port, keepalive, persistent; /* persistent: clean session off */
    int backoff_min, backoff_max;    /* reconnect delay, seconds: doubles from min up to max */
    int status_s;                /* status republished at least this often */
    char client[64];             /* "" : fixel-kiosk-HOSTNAME-PID */
    char prefix[KIOSK_TOPIC_MAX];/* control and status topics live below it; "" : none */
    char auth[KIOSK_PATH_MAX];   /* file: user on the first line, password on the second */
    int tls, verify;             /* verify: check the broker's name against its certificate */
    char ca[KIOSK_PATH_MAX], cert[KIOSK_PATH_MAX], key[KIOSK_PATH_MAX];
    int nsubs;
    kiosk_sub subs[KIOSK_MQTT_SUBS];
} kiosk_mqtt_cfg;

/* "screen": how the screen is switched and dimmed (kiosk_screen.c). */
typedef struct kiosk_screen_cfg {
    char backlight[64];        /* "auto" (the first, if any), "none" or a device name */
    char sysfs[KIOSK_PATH_MAX]; /* the backlight class directory ("": /sys/class/backlight) */
    int brightness;            /* percent set at start; -1: leave it */
    int idle_min;              /* blank after this many minutes without input; 0: never */
    kiosk_sched sched[KIOSK_SCHED_MAX]; /* "schedule" lines: when the screen is on */
    int nsched;
} kiosk_screen_cfg;

/* "output NAME [rotation=R] [size=WxH]" starts one screen's section
 * (docs/kiosk.md, "Several screens"): the grid, title and widgets after it,
 * up to the next output line, are that screen's. NAME is the connector
 * (HDMI-A-1, DSI-1...), searched on every card as FIXEL_CONNECTOR is. */
#define KIOSK_MAX_OUTPUTS 4 /* FX_APP_MAX_DISPLAYS */
#define KIOSK_OUTPUT_MAX 32 /* connector names, including the NUL */
typedef struct kiosk_output {
    char name[KIOSK_OUTPUT_MAX];
    int rotation;              /* -1: the display's default (FIXEL_ROTATION, the panel's orientation) */
    int cols, rows;
    int width, height;         /* 0: the display's size */
    char title[KIOSK_TEXT_MAX];
    int line;                  /* where it was declared */
} kiosk_output;
#include "kiosk_pages.h"

typedef struct kiosk_config {
    int cols, rows;
    int width, height;         /* 0: the display's size */
    int stale_ms;              /* a source silent this long is marked stale */
    int history;               /* ring buffer entries shown (<= KIOSK_HIST_MAX) */
    uint32_t bg, panel, fg;
    char title[KIOSK_TEXT_MAX];
    int ncols;                 /* CSV header in force (0: none); from "columns" or a data line */
    char colname[KIOSK_CSV_MAX][KIOSK_NAME_MAX]; /* the source each column feeds, by name */
    uint32_t changed;          /* sources (bit i = source i) the last data line updated */
    int nwidgets, nsources;
    kiosk_widget widgets[KIOSK_MAX_WIDGETS];
    kiosk_source sources[KIOSK_MAX_SOURCES];
    char msg[96];              /* the last range message (from kiosk_keys) */
    kiosk_mqtt_cfg mqtt;
    kiosk_screen_cfg screen;
    int noutputs;              /* 0: one screen, the layout above (as before sections existed) */
    kiosk_output outputs[KIOSK_MAX_OUTPUTS];
    kiosk_pages_cfg pg;        /* pages, carousel, touch, buttons (kiosk_pages.h) */
    const char *errat;         /* parser scratch: the token an error is about */
    int errline, errcol;       /* of the last config error, 1-based (col 1 when the line as a whole is wrong) */
} kiosk_config;

/* Parse a config in buf[0..len). On error returns -1 and writes "line N:
 * reason" into err (size errsize); 0 on success. */
int kiosk_config_parse(kiosk_config *k, const char *buf, size_t len, char *err, size_t errsize);

/* The one table of everything a config or a data stream may hold (issue
 * #26): each directive, widget key and data value with its type and range.
 * kiosk_config_parse takes every range from here, and an out-of-range value
 * is an error naming it ("col=99: expected 0..63"); fixel-kiosk --keys
 * prints it. type: 'i' integer, 'p' integer pair AxB, 'm' decimal number
 * (min/max in thousandths), 'c' colour #rrggbb, 't' text, 'f' path, 'w' one of
 * the words in help. widgets: the widget types (bit per kiosk_type) the key
 * applies to; 0 for directives and data. */
typedef struct kiosk_key {
    const char *scope; /* "directive", "widget" or "data" */
    const char *name;
    char type;
    int64_t min, max;
    unsigned widgets;
    const char *help;
} kiosk_key;
extern const kiosk_key kiosk_keys[]; /* NULL name ends it */
const kiosk_key *kiosk_key_find(const char *scope, const char *name, size_t n);

/* Parse a decimal "[-+]digits[.digits]" of exactly len characters into
 * milli-units (rounded half away from zero). Returns 0 or -1. */
/* Every number (data values, min, max) lies within +-KIOSK_VALUE_MAX (10^15,
 * in thousandths +-10^18): differences of two stay below 2^61, and
 * widgets scale them with a 96-bit muldiv (issue #26). */
#define KIOSK_VALUE_MAX 1000000000000000LL
int kiosk_parse_milli(const char *s, size_t len, int64_t *out);

/* "on"/"1" -> 1, "off"/"0" -> 0 (any case, trailing blanks and line
 * ends allowed), anything else of exactly len bytes (a NUL included) -> -1. */
int kiosk_parse_onoff(const char *s, size_t len);

typedef enum kiosk_line_result {
    KIOSK_LINE_OK = 0,      /* a value was stored */
    KIOSK_LINE_IGNORED = 1, /* blank, comment, or a name no widget shows */
    KIOSK_LINE_HEADER = 2,  /* a CSV header: it names the columns of the rows after it */
    KIOSK_LINE_BAD = -1     /* malformed: counted and shown, never fatal */
} kiosk_line_result;

/* One data line (no newline) at time now_ms; docs/kiosk.md has the full
 * grammar. "name=value" or "name,value": sources feeding number/gauge/bar/
 * spark widgets need a number, text widgets take any printable value, image
 * widgets a path. "name=v1,v2,..." sets every cell of a heat map (row-major),
 * "name[R]=v1,..." one row. A line of three or more comma-separated names is
 * a CSV header; while one is in force, a line with that many fields and no
 * '=' is a CSV row, column i feeding the source named by header field i.
 * Returns a kiosk_line_result; on OK *src is one source updated and
 * k->changed has a bit for every source updated. */
int kiosk_data_line(kiosk_config *k, const char *line, size_t len, int64_t now_ms, int *src);

/* Give source s the value v[0..n) (a number, text, path or heat cells as
 * its widgets want) at now_ms, as a "name=value" line would. MQTT topics
 * bound to a source use it. Returns KIOSK_LINE_OK or KIOSK_LINE_BAD. */
int kiosk_set_value(kiosk_config *k, int s, const char *v, size_t n, int64_t now_ms);

/* Does topic filter f (MQTT 3.1.1: + one level, # the rest) accept topic
 * t[0..n)? Topics starting with '$' only match filters that name it. */
int kiosk_topic_match(const char *f, const char *t, size_t n);

/* One step of a JSON path: a member name, or an array index (name NULL). */
typedef struct kiosk_jstep { const char *name; size_t len; int index; } kiosk_jstep;
/* Split a path checked by the config parser into steps; returns their count. */
int kiosk_jpath_steps(const char *path, kiosk_jstep *steps, int max);

/* History entry i of source s, 0 = oldest of the last n (n <= count). */
int64_t kiosk_hist_at(const kiosk_source *s, uint32_t n, uint32_t i);

/* Format milli-units with d decimals (rounded) into buf. */
void kiosk_format_milli(char *buf, size_t size, int64_t v, int d);

#endif
