/* SPDX-License-Identifier: MIT */
/* fixel — DRM cards and their outputs by name. A Raspberry Pi 5 has one card
 * per display engine (HDMI, DSI, DPI, composite) and their numbers depend on
 * probe order, so a display is named by what does not move: the card's
 * driver ("vc4", "drm-rp1-dsi") or its udev by-path name ("platform-gpu",
 * "pci-0000:00:02.0"), and a connector ("HDMI-A-2") searched on every card.
 * docs/displays.md has the syntax. Enumeration (fx_drm_cards) is apart from
 * the choice (fx_card_pick_output, pure) so the choice is tested on fake
 * cards. */
#ifndef FIXEL_CARDS_H
#define FIXEL_CARDS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define FX_CARD_CONNECTORS_MAX 16
#define FX_CARDS_MAX 16

typedef struct fx_connector_desc {
    uint32_t id;       /* the KMS object id */
    char name[32];     /* "HDMI-A-1": type name and the per-card type index */
    int connected;     /* 1 connected, 0 disconnected, -1 unknown */
    int modes;         /* number of modes (0: nothing to show on) */
} fx_connector_desc;

typedef struct fx_card_desc {
    int minor;             /* N of /dev/dri/cardN */
    char path[64];         /* "/dev/dri/card0" */
    char driver[32];       /* DRM driver name: "vc4", "bochs-drm", "virtio_gpu"; "" unknown */
    char path_name[160];   /* udev's by-path name (the /dev/dri/by-path/NAME-card link):
                              "platform-gpu", "pci-0000:00:02.0"; "" unknown */
    int error;             /* 0, or the negative errno that kept it from being read */
    int nconn;
    fx_connector_desc conn[FX_CARD_CONNECTORS_MAX];
} fx_card_desc;

/* 1 when spec names card c: "cardN", "/dev/dri/cardN", the driver name
 * ('-' and '_' alike: "virtio-gpu" is virtio_gpu), the by-path name with or
 * without its "-card" suffix, or a tail of the by-path name from one of
 * its components on ("platform-1f00130000.dsi" names
 * "platform-1000120000.pcie-pci-0000:01:00.0-platform-1f00130000.dsi"). */
int fx_card_matches(const fx_card_desc *c, const char *spec);

typedef enum fx_card_pick {
    FX_PICK_OK = 0,
    FX_PICK_NO_CARD,        /* a card was named and none matches */
    FX_PICK_NO_CONNECTOR,   /* a connector was named and no matching card has it */
    FX_PICK_DISCONNECTED,   /* the named connector exists but has no modes (*card, *conn set) */
    FX_PICK_NONE_CONNECTED, /* nothing named and no connected connector with modes */
} fx_card_pick;

/* Choose the output. device: a card spec as above or NULL/"" (every card).
 * connector: NULL/"" (the first connected connector with modes, cards in
 * order), "NAME" (the first card of those allowed having it: connected ones
 * first, then any with modes, e.g. forced on), or "CARD:NAME" (CARD a card
 * spec; it splits at the last ':' since by-path names hold ':'). Cards with
 * an error are skipped. *card and *conn index cards[] and cards[*card].conn[]. */
fx_card_pick fx_card_pick_output(const fx_card_desc *cards, int n, const char *device,
                                 const char *connector, int *card, int *conn);

/* Describes every /dev/dri/cardN (natural order, at most max) into out:
 * driver, by-path name and connectors (a full probe of each). Returns how
 * many; 0 without libdrm. A card that cannot be opened is listed with
 * error set. */
int fx_drm_cards(fx_card_desc *out, int max);

#ifdef __cplusplus
}  /* extern "C" */
#endif
#endif
