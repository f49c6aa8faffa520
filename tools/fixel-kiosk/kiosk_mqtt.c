/* SPDX-License-Identifier: MIT */
/* fixel-kiosk's MQTT client: see kiosk_mqtt.h. Built with libmosquitto and
 * cJSON when pkg-config finds them (tools/fixel-kiosk/kiosk.mk), else every
 * entry point says MQTT is missing. */
#include "kiosk_mqtt.h"
#include "fixel/files.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <unistd.h>

#ifdef KIOSK_HAVE_MQTT
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <sys/stat.h>
#include <time.h>

#include <cJSON.h>
#include <mosquitto.h>
#include <mqtt_protocol.h>

struct kmq {
    kiosk_mqtt_cfg cfg;
    struct mosquitto *mosq;
    pthread_t thread;
    int started;
    pthread_mutex_t lock;
    pthread_cond_t room;       /* the main loop took messages out */
    atomic_int stop; /* read by the client thread outside the lock */
    kmq_state st;
    int sock_up;               /* mosquitto has a socket (maybe not yet CONNACKed) */
    int backoff;               /* seconds before the next attempt */
    char will_topic[KIOSK_TOPIC_MAX + 16];
    char user[256], pass[256];
    /* the ring */
    kmq_msg *q;
    unsigned head, count;
    mosquitto_property *props; /* CONNECT: maximum packet size, session expiry */
    atomic_int renew;          /* reconnect now: the control prefix (and will) changed */
    int will_dirty;            /* under lock: the will follows a new prefix at the next CONNECT */
    int wake_fd;               /* eventfd: the main loop polls it (kmq_wake_fd) */
};

/* Tell the main loop there is news (a message queued, the connection's
 * state changed) now rather than at its next timer tick: messages waited up
 * to the tick's 100 ms before (make bench-kiosk measured p50 50 ms). */
static void wake(kmq *m)
{
    uint64_t one = 1;
    if (m->wake_fd >= 0 && write(m->wake_fd, &one, sizeof one) < 0) {
        /* EAGAIN: the counter is full, so the loop is being woken anyway */
    }
}

int kmq_available(void) { return 1; }

static void set_error(kmq *m, const char *what)
{
    pthread_mutex_lock(&m->lock);
    if (strcmp(m->st.last_error, what)) {
        snprintf(m->st.last_error, sizeof m->st.last_error, "%s", what);
        fprintf(stderr, "fixel-kiosk: mqtt %s:%d: %s\n", m->cfg.host, m->cfg.port, what);
    }
    pthread_mutex_unlock(&m->lock);
}

static void subscribe_all(kmq *m)
{
    kiosk_mqtt_cfg *c = &m->cfg;
    for (int i = 0; i < c->nsubs; i++) mosquitto_subscribe(m->mosq, NULL, c->subs[i].topic, c->subs[i].qos);
    if (c->prefix[0]) {
        char t[KIOSK_TOPIC_MAX + 16];
        snprintf(t, sizeof t, "%s/set/#", c->prefix);
        mosquitto_subscribe(m->mosq, NULL, t, 1);
    }
}

static void on_connect(struct mosquitto *mosq, void *user, int rc)
{
    kmq *m = user;
    (void)mosq;
    if (rc != 0) {
        char why[96];
        snprintf(why, sizeof why, "refused: %s", mosquitto_connack_string(rc));
        set_error(m, why);
        return;
    }
    pthread_mutex_lock(&m->lock);
    m->st.connected = 1;
    m->st.offline_since = 0;
    m->st.connects++;
    m->st.last_error[0] = 0;
    m->backoff = m->cfg.backoff_min;
    subscribe_all(m);
    /* under the lock: a reload may change the prefix (kmq_set_subs) */
    if (m->cfg.prefix[0]) mosquitto_publish(m->mosq, NULL, m->will_topic, 6, "online", 1, true);
    pthread_mutex_unlock(&m->lock);
    fprintf(stderr, "fixel-kiosk: mqtt connected to %s:%d\n", m->cfg.host, m->cfg.port);
    wake(m);
}

static void went_offline(kmq *m)
{
    pthread_mutex_lock(&m->lock);
    if (m->st.connected || !m->st.offline_since) m->st.offline_since = (int64_t)time(NULL);
    m->st.connected = 0;
    pthread_mutex_unlock(&m->lock);
    wake(m);
}

static void on_disconnect(struct mosquitto *mosq, void *user, int rc)
{
    (void)mosq;
    (void)rc;
    went_offline(user);
}

static void on_message(struct mosquitto *mosq, void *user, const struct mosquitto_message *msg)
{
    kmq *m = user;
    (void)mosq;
    size_t tl = msg->topic ? strlen(msg->topic) : 0;
    pthread_mutex_lock(&m->lock);
    if (tl == 0 || tl >= KMQ_TOPIC_MAX) {
        m->st.dropped++;
        pthread_mutex_unlock(&m->lock);
        return;
    }
    /* a full ring waits for the main loop (it drains every tick) rather
     * than growing; after 2 s of no room the message is dropped and counted */
    struct timespec dl;
    clock_gettime(CLOCK_REALTIME, &dl);
    dl.tv_sec += 2;
    while (m->count == KMQ_QUEUE && !m->stop)
        if (pthread_cond_timedwait(&m->room, &m->lock, &dl) == ETIMEDOUT) break;
    if (m->count == KMQ_QUEUE || m->stop) {
        m->st.dropped++;
        pthread_mutex_unlock(&m->lock);
        return;
    }
    kmq_msg *e = &m->q[(m->head + m->count) % KMQ_QUEUE];
    memcpy(e->topic, msg->topic, tl + 1);
    e->oversize = msg->payloadlen < 0 || msg->payloadlen > KMQ_PAYLOAD_MAX;
    e->plen = e->oversize ? 0 : (size_t)msg->payloadlen;
    if (e->plen) memcpy(e->payload, msg->payload, e->plen);
    e->payload[e->plen] = 0;
    m->count++;
    pthread_mutex_unlock(&m->lock);
    wake(m);
}

/* Sleep s seconds in short steps, so kmq_stop never waits for a backoff. */
static void nap(kmq *m, int s)
{
    for (int i = 0; i < s * 10 && !m->stop; i++) {
        struct timespec ts = {0, 100 * 1000000L};
        nanosleep(&ts, NULL);
    }
}

static void *run(void *arg)
{
    kmq *m = arg;
    int first = 1;
    while (!m->stop) {
        if (!m->sock_up) {
            pthread_mutex_lock(&m->lock);
            if (m->will_dirty) {
                if (m->cfg.prefix[0]) mosquitto_will_set(m->mosq, m->will_topic, 7, "offline", 1, true);
                else mosquitto_will_clear(m->mosq);
                m->will_dirty = 0;
            }
            pthread_mutex_unlock(&m->lock);
            int rc = first ? mosquitto_connect_bind_v5(m->mosq, m->cfg.host, m->cfg.port, m->cfg.keepalive, NULL,
                                                       m->props)
                           : mosquitto_reconnect(m->mosq); /* the same CONNECT properties */
            if (rc == MOSQ_ERR_SUCCESS) {
                first = 0;
                m->sock_up = 1;
                continue;
            }
            set_error(m, rc == MOSQ_ERR_ERRNO ? strerror(errno) : mosquitto_strerror(rc));
            went_offline(m);
            /* doubling from backoff up to backoff_max; reset on a CONNACK */
            int d = m->backoff;
            m->backoff = m->backoff * 2 > m->cfg.backoff_max ? m->cfg.backoff_max : m->backoff * 2;
            nap(m, d);
            continue;
        }
        int rc = mosquitto_loop(m->mosq, 100, 1);
        if (rc != MOSQ_ERR_SUCCESS && !m->stop && m->renew) {
            /* kmq_set_subs disconnected for a new prefix: back at once */
            m->renew = 0;
            went_offline(m);
            m->sock_up = 0;
            first = 0;
            continue;
        }
        if (rc != MOSQ_ERR_SUCCESS && !m->stop) {
            set_error(m, rc == MOSQ_ERR_ERRNO ? strerror(errno)
                       : rc == MOSQ_ERR_CONN_LOST ? "connection lost" : mosquitto_strerror(rc));
            went_offline(m);
            m->sock_up = 0;
            first = 0;
            int d = m->backoff;
            m->backoff = m->backoff * 2 > m->cfg.backoff_max ? m->cfg.backoff_max : m->backoff * 2;
            nap(m, d);
        }
    }
    return NULL;
}

/* user and password from a file of two lines: never on the command line,
 * where ps would show them to every user */
static int read_auth(kmq *m, char *err, size_t errsize)
{
    char why[160];
    FILE *f = fx_fopen_regular(m->cfg.auth, NULL, why, sizeof why); /* a FIFO must not hang the kiosk */
    if (!f) {
        snprintf(err, errsize, "mqtt auth=%s: %s", m->cfg.auth, why);
        return -1;
    }
    struct stat st;
    if (fstat(fileno(f), &st) == 0 && (st.st_mode & 077))
        fprintf(stderr, "fixel-kiosk: warning: %s is readable by others (chmod 600)\n", m->cfg.auth);
    int ok = fgets(m->user, sizeof m->user, f) != NULL;
    if (ok && !fgets(m->pass, sizeof m->pass, f)) m->pass[0] = 0;
    fclose(f);
    m->user[strcspn(m->user, "\r\n")] = 0;
    m->pass[strcspn(m->pass, "\r\n")] = 0;
    if (!ok || !m->user[0]) {
        snprintf(err, errsize, "mqtt auth=%s: expected a user line and a password line", m->cfg.auth);
        return -1;
    }
    return 0;
}

kmq *kmq_start(const kiosk_mqtt_cfg *cfg, const char *version, char *err, size_t errsize)
{
    (void)version;
    mosquitto_lib_init(); /* kmq_stop's mosquitto_lib_cleanup pairs with it */
    kmq *m = calloc(1, sizeof *m);
    if (!m || !(m->q = calloc(KMQ_QUEUE, sizeof *m->q))) {
        if (m) free(m);
        snprintf(err, errsize, "mqtt: out of memory");
        return NULL;
    }
    m->cfg = *cfg;
    m->backoff = cfg->backoff_min;
    m->wake_fd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC); /* -1: the tick still drains the ring */
    pthread_mutex_init(&m->lock, NULL);
    pthread_cond_init(&m->room, NULL);
    m->st.offline_since = (int64_t)time(NULL);
    char id[64];
    if (cfg->client[0]) snprintf(id, sizeof id, "%s", cfg->client);
    else {
        char h[32] = "host";
        gethostname(h, sizeof h - 1);
        h[sizeof h - 1] = 0;
        snprintf(id, sizeof id, "fixel-kiosk-%s-%ld", h, (long)getpid());
    }
    m->mosq = mosquitto_new(id, !cfg->persistent, m);
    const char *fail = NULL;
    if (!m->mosq) fail = "mosquitto_new failed";
    else if (cfg->auth[0] && read_auth(m, err, errsize) < 0) fail = "";
    else if (cfg->auth[0] && mosquitto_username_pw_set(m->mosq, m->user, m->pass[0] ? m->pass : NULL))
        fail = "cannot set the user";
    else if (cfg->tls && mosquitto_tls_set(m->mosq, cfg->ca, NULL, cfg->cert[0] ? cfg->cert : NULL,
                                           cfg->key[0] ? cfg->key : NULL, NULL))
        fail = "TLS set-up failed (ca/cert/key files readable? key matches cert?)";
    else if (cfg->tls && mosquitto_tls_insecure_set(m->mosq, !cfg->verify)) fail = "TLS set-up failed";
    if (!fail && cfg->prefix[0]) {
        snprintf(m->will_topic, sizeof m->will_topic, "%s/online", cfg->prefix);
        if (mosquitto_will_set(m->mosq, m->will_topic, 7, "offline", 1, true)) fail = "cannot set the last will";
    }
    memset(m->pass, 0, sizeof m->pass); /* libmosquitto has its own copy */
    if (fail) {
        if (*fail) snprintf(err, errsize, "mqtt: %s", fail);
        if (m->mosq) mosquitto_destroy(m->mosq);
        free(m->q);
        free(m);
        return NULL;
    }
    /* MQTT v5 for its Maximum Packet Size: the broker drops what is larger
     * instead of sending it, so a 256 KiB (or 256 MiB) publish is never
     * buffered whole by libmosquitto before the kiosk could refuse it. v5
     * ends a session at disconnect unless it has an expiry: a persistent one
     * never expires, as in 3.1.1. */
    if (!fail && (mosquitto_int_option(m->mosq, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V5) ||
                  mosquitto_property_add_int32(&m->props, MQTT_PROP_MAXIMUM_PACKET_SIZE, KMQ_PACKET_MAX) ||
                  (cfg->persistent &&
                   mosquitto_property_add_int32(&m->props, MQTT_PROP_SESSION_EXPIRY_INTERVAL, UINT32_MAX))))
        fail = "cannot ask for MQTT v5";
    if (fail) {
        if (*fail) snprintf(err, errsize, "mqtt: %s", fail);
        mosquitto_property_free_all(&m->props);
        if (m->mosq) mosquitto_destroy(m->mosq);
        free(m->q);
        free(m);
        return NULL;
    }
    mosquitto_threaded_set(m->mosq, true);
    mosquitto_connect_callback_set(m->mosq, on_connect);
    mosquitto_disconnect_callback_set(m->mosq, on_disconnect);
    mosquitto_message_callback_set(m->mosq, on_message);
    if (pthread_create(&m->thread, NULL, run, m)) {
        snprintf(err, errsize, "mqtt: cannot start its thread");
        mosquitto_property_free_all(&m->props);
        mosquitto_destroy(m->mosq);
        free(m->q);
        free(m);
        return NULL;
    }
    m->started = 1;
    return m;
}

void kmq_stop(kmq *m)
{
    if (!m) return;
    pthread_mutex_lock(&m->lock);
    int up = m->st.connected;
    pthread_mutex_unlock(&m->lock);
    if (m->cfg.prefix[0] && up) {
        /* a clean disconnect sends no will: say it ourselves */
        int mid;
        if (mosquitto_publish(m->mosq, &mid, m->will_topic, 7, "offline", 1, true) == MOSQ_ERR_SUCCESS) {
            struct timespec ts = {0, 100 * 1000000L};
            nanosleep(&ts, NULL); /* the thread's loop writes it out */
        }
    }
    pthread_mutex_lock(&m->lock);
    m->stop = 1;
    pthread_cond_broadcast(&m->room);
    pthread_mutex_unlock(&m->lock);
    mosquitto_disconnect(m->mosq);
    if (m->started) {
        /* The thread may sit in a blocking connect to a broker that does not
         * answer (minutes of SYN retries): a stopping kiosk waits 2 s, then
         * leaves it to the process exit rather than hang until systemd's
         * SIGKILL. Its state stays allocated, since it may still use it. */
        struct timespec until;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_sec += 2;
        if (pthread_timedjoin_np(m->thread, NULL, &until) != 0) {
            pthread_detach(m->thread);
            return;
        }
    }
    mosquitto_destroy(m->mosq);
    mosquitto_property_free_all(&m->props);
    if (m->wake_fd >= 0) close(m->wake_fd);
    pthread_cond_destroy(&m->room);
    pthread_mutex_destroy(&m->lock);
    free(m->q);
    free(m);
    mosquitto_lib_cleanup();
}

int kmq_wake_fd(kmq *m) { return m ? m->wake_fd : -1; }

int kmq_take(kmq *m, kmq_msg *out)
{
    int got = 0;
    pthread_mutex_lock(&m->lock);
    if (m->count) {
        kmq_msg *e = &m->q[m->head];
        memcpy(out->topic, e->topic, strlen(e->topic) + 1);
        out->plen = e->plen;
        out->oversize = e->oversize;
        memcpy(out->payload, e->payload, e->plen + 1);
        m->head = (m->head + 1) % KMQ_QUEUE;
        m->count--;
        pthread_cond_signal(&m->room);
        got = 1;
    }
    pthread_mutex_unlock(&m->lock);
    return got;
}

void kmq_get_state(kmq *m, kmq_state *st)
{
    pthread_mutex_lock(&m->lock);
    *st = m->st;
    pthread_mutex_unlock(&m->lock);
}

void kmq_publish(kmq *m, const char *sub, const char *payload, int retain)
{
    char t[KIOSK_TOPIC_MAX + 32];
    pthread_mutex_lock(&m->lock);
    int up = m->st.connected && m->cfg.prefix[0];
    snprintf(t, sizeof t, "%s/%s", m->cfg.prefix, sub);
    pthread_mutex_unlock(&m->lock);
    if (!up) return;
    mosquitto_publish(m->mosq, NULL, t, (int)strlen(payload), payload, 1, retain != 0);
}

int kmq_publish_to(kmq *m, const char *topic, const char *payload, int qos, int retain)
{
    if (!m) return -1;
    pthread_mutex_lock(&m->lock);
    int up = m->st.connected;
    pthread_mutex_unlock(&m->lock);
    if (!up) return -1;
    return mosquitto_publish(m->mosq, NULL, topic, (int)strlen(payload), payload, qos, retain != 0) == MOSQ_ERR_SUCCESS
               ? 0 : -1;
}

void kmq_set_subs(kmq *m, const kiosk_mqtt_cfg *cfg)
{
    pthread_mutex_lock(&m->lock);
    for (int i = 0; i < m->cfg.nsubs; i++) mosquitto_unsubscribe(m->mosq, NULL, m->cfg.subs[i].topic);
    m->cfg.nsubs = cfg->nsubs;
    memcpy(m->cfg.subs, cfg->subs, sizeof cfg->subs);
    if (strcmp(m->cfg.prefix, cfg->prefix)) {
        /* A new control prefix: the old one is left (its control topic
         * unsubscribed, its online flag says offline) and the new one
         * taken, will included, or the kiosk would answer on a prefix the
         * main loop no longer reads and never on the new one. */
        if (m->cfg.prefix[0]) {
            char t[KIOSK_TOPIC_MAX + 16];
            snprintf(t, sizeof t, "%s/set/#", m->cfg.prefix);
            mosquitto_unsubscribe(m->mosq, NULL, t);
            if (m->st.connected) mosquitto_publish(m->mosq, NULL, m->will_topic, 7, "offline", 1, true);
        }
        memcpy(m->cfg.prefix, cfg->prefix, sizeof m->cfg.prefix);
        if (m->cfg.prefix[0]) snprintf(m->will_topic, sizeof m->will_topic, "%s/online", m->cfg.prefix);
        m->will_dirty = 1; /* set by the client thread before its next CONNECT, which reads it */
        /* The broker holds the will given at CONNECT: a clean disconnect
         * (no will sent) and an immediate reconnect hand it the new one;
         * on_connect then subscribes PREFIX/set/# and says online. */
        if (m->st.connected) {
            m->renew = 1;
            mosquitto_disconnect(m->mosq);
        }
        pthread_mutex_unlock(&m->lock);
        return;
    }
    /* subscribing again also brings the retained values of the topics */
    if (m->st.connected) subscribe_all(m);
    pthread_mutex_unlock(&m->lock);
}

int kmq_json_field(const char *payload, size_t n, const char *path, char *out, size_t size)
{
    kiosk_jstep st[KIOSK_JPATH_DEPTH];
    int ns = kiosk_jpath_steps(path, st, KIOSK_JPATH_DEPTH);
    if (ns <= 0) return -1;
    /* cJSON refuses nesting deeper than CJSON_NESTING_LIMIT (1000): a
     * hostile payload costs a bounded stack and at most a few times its size */
    cJSON *root = cJSON_ParseWithLength(payload, n);
    if (!root) return -1;
    const cJSON *j = root;
    for (int i = 0; i < ns && j; i++) {
        if (st[i].name) {
            char name[KIOSK_JPATH_MAX];
            memcpy(name, st[i].name, st[i].len);
            name[st[i].len] = 0;
            j = cJSON_IsObject(j) ? cJSON_GetObjectItemCaseSensitive(j, name) : NULL;
        } else
            j = cJSON_IsArray(j) ? cJSON_GetArrayItem(j, st[i].index) : NULL;
    }
    int r = -1;
    if (j && cJSON_IsNumber(j) && isfinite(j->valuedouble) && fabs(j->valuedouble) <= 1e15) {
        /* thousandths, as the kiosk keeps numbers; trailing zeros dropped */
        int len = snprintf(out, size, "%.3f", j->valuedouble);
        if (len > 0 && (size_t)len < size) {
            while (len > 1 && out[len - 1] == '0') out[--len] = 0;
            if (out[len - 1] == '.') out[--len] = 0;
            r = 0;
        }
    } else if (j && cJSON_IsString(j) && strlen(j->valuestring) < size) {
        memcpy(out, j->valuestring, strlen(j->valuestring) + 1);
        r = 0;
    } else if (j && cJSON_IsBool(j) && size >= 2) {
        snprintf(out, size, "%d", cJSON_IsTrue(j) ? 1 : 0);
        r = 0;
    }
    cJSON_Delete(root);
    return r;
}

#else /* built without libmosquitto or cJSON */

struct kmq { int unused; };
int kmq_available(void) { return 0; }
kmq *kmq_start(const kiosk_mqtt_cfg *cfg, const char *version, char *err, size_t errsize)
{
    (void)cfg;
    (void)version;
    snprintf(err, errsize, "this fixel-kiosk was built without MQTT (install libmosquitto-dev and libcjson-dev, "
                           "then rebuild)");
    return NULL;
}
void kmq_stop(kmq *m) { (void)m; }
int kmq_take(kmq *m, kmq_msg *out) { (void)m; (void)out; return 0; }
int kmq_wake_fd(kmq *m) { (void)m; return -1; }
void kmq_get_state(kmq *m, kmq_state *st) { (void)m; memset(st, 0, sizeof *st); }
void kmq_publish(kmq *m, const char *sub, const char *payload, int retain)
{
    (void)m; (void)sub; (void)payload; (void)retain;
}
int kmq_publish_to(kmq *m, const char *topic, const char *payload, int qos, int retain)
{
    (void)m; (void)topic; (void)payload; (void)qos; (void)retain;
    return -1;
}
void kmq_set_subs(kmq *m, const kiosk_mqtt_cfg *cfg) { (void)m; (void)cfg; }
int kmq_json_field(const char *payload, size_t n, const char *path, char *out, size_t size)
{
    (void)payload; (void)n; (void)path; (void)out; (void)size;
    return -1;
}
#endif
