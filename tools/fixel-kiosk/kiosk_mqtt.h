/* SPDX-License-Identifier: MIT */
/* fixel-kiosk's MQTT client (libmosquitto on a thread of its own, cJSON).
 * The thread only moves bytes: it connects, reconnects with backoff,
 * subscribes and queues what arrives into a fixed ring; the kiosk's main
 * loop takes the messages out and does everything else (matching topics to
 * sources, control, drawing). A slow main loop holds the thread back (the
 * broker then holds the messages) instead of growing memory. */
#ifndef FIXEL_KIOSK_MQTT_H
#define FIXEL_KIOSK_MQTT_H

#include <stddef.h>
#include <stdint.h>

#include "kiosk.h"

#define KMQ_TOPIC_MAX 256      /* longer topics are dropped and counted bad */
#define KMQ_PAYLOAD_MAX 8192   /* longer payloads arrive as "oversize": counted bad, never copied */
/* The MQTT v5 Maximum Packet Size the kiosk asks for: the broker drops
 * larger messages for this client (they never reach it, so they cannot be
 * counted). Between KMQ_PAYLOAD_MAX and this they arrive and count bad: a
 * 256 KiB payload is a bad line, and the most libmosquitto ever holds for
 * one message is 1 MiB, freed as soon as it is counted. */
#define KMQ_PACKET_MAX (1024 * 1024)
#define KMQ_QUEUE 128          /* messages waiting for the main loop */

typedef struct kmq_msg {
    char topic[KMQ_TOPIC_MAX];
    char payload[KMQ_PAYLOAD_MAX + 1]; /* NUL-terminated copy (the payload may hold NULs too) */
    size_t plen;
    int oversize;
} kmq_msg;

typedef struct kmq_state {
    int connected;
    int64_t offline_since;     /* wall-clock seconds; 0 while connected */
    uint32_t connects;         /* successful connections so far */
    uint32_t dropped;          /* messages lost to a full queue, over-long topics */
    char last_error[96];       /* why the last attempt failed ("" : none) */
} kmq_state;

typedef struct kmq kmq;

/* Whether this fixel-kiosk was built with MQTT. */
int kmq_available(void);
/* Start the client thread for cfg (copied). NULL and a reason in err when
 * the configuration cannot work at all (unreadable auth file, no TLS); a
 * broker that is down is not an error: the thread retries with backoff. */
kmq *kmq_start(const kiosk_mqtt_cfg *cfg, const char *version, char *err, size_t errsize);
/* Publish "offline" (retained), disconnect and join the thread. */
void kmq_stop(kmq *m);
/* Take the oldest queued message into *out: 1, or 0 when there is none. */
int kmq_take(kmq *m, kmq_msg *out);
/* An fd that becomes readable when a message is queued or the connection
 * changes (an eventfd: read its 8-byte counter to clear it), for the main
 * loop's poll; -1 when there is none (then poll kmq_take on a timer). */
int kmq_wake_fd(kmq *m);
void kmq_get_state(kmq *m, kmq_state *st);
/* Publish payload on PREFIX/sub (retained or not); dropped while offline. */
void kmq_publish(kmq *m, const char *sub, const char *payload, int retain);
/* Publish payload on topic (a button's message) with qos and retain: 0, or
 * -1 when it was not sent (offline, no client, refused). */
int kmq_publish_to(kmq *m, const char *topic, const char *payload, int qos, int retain);
/* A reloaded config's subscriptions replace the old ones (broker settings
 * stay as started). */
void kmq_set_subs(kmq *m, const kiosk_mqtt_cfg *cfg);
/* Field path of a JSON payload as text into out ("21.5", a string's text,
 * 1/0 for booleans): 0, or -1 (not JSON, no such field, not a scalar). */
int kmq_json_field(const char *payload, size_t n, const char *path, char *out, size_t size);

#endif
