/* SPDX-License-Identifier: MIT */
/* Naming DRM cards and choosing the output (boards/linux/display/cards.c) on
 * fake card descriptions: a Raspberry Pi 5 (one card per display engine),
 * a Pi 4 (one vc4 card with three connectors), two cards whose connectors
 * share a name (Linux numbers each connector type across all cards, so
 * names are unique while it runs, but the choice must not depend on it). */
#include <stdio.h>
#include <string.h>

#include "fixel/cards.h"
#include "fx_test.h"

static void conn(fx_card_desc *c, const char *name, int connected, int modes)
{
    fx_connector_desc *o = &c->conn[c->nconn];
    memset(o, 0, sizeof *o);
    o->id = (uint32_t)(100 + c->nconn);
    strncpy(o->name, name, sizeof o->name - 1);
    o->connected = connected;
    o->modes = modes;
    c->nconn++;
}

static void card(fx_card_desc *c, int minor, const char *driver, const char *path_name)
{
    memset(c, 0, sizeof *c);
    c->minor = minor;
    snprintf(c->path, sizeof c->path, "/dev/dri/card%d", minor);
    strncpy(c->driver, driver, sizeof c->driver - 1);
    strncpy(c->path_name, path_name, sizeof c->path_name - 1);
}

/* Pi 5 with a DSI panel and nothing on HDMI: card0 is v3d (render only,
 * no KMS), card1 vc4 (HDMI), card2 the RP1 DSI. */
static int pi5(fx_card_desc *c)
{
    card(&c[0], 0, "v3d", "platform-1002000000.v3d");
    c[0].error = -19;
    card(&c[1], 1, "vc4", "platform-axi:gpu");
    conn(&c[1], "HDMI-A-1", 0, 0);
    conn(&c[1], "HDMI-A-2", 0, 0);
    card(&c[2], 2, "drm-rp1-dsi", "platform-1000120000.pcie-pci-0000:01:00.0-platform-1f00130000.dsi");
    conn(&c[2], "DSI-1", 1, 1);
    return 3;
}

FX_TEST(cards_match_by_number_path_driver_and_by_path)
{
    fx_card_desc c[3];
    pi5(c);
    FX_CHECK(fx_card_matches(&c[2], "card2"));
    FX_CHECK(fx_card_matches(&c[2], "/dev/dri/card2"));
    FX_CHECK(!fx_card_matches(&c[2], "card1"));
    FX_CHECK(!fx_card_matches(&c[2], "card"));
    FX_CHECK(!fx_card_matches(&c[2], "card2x"));
    FX_CHECK(fx_card_matches(&c[2], "drm-rp1-dsi"));
    FX_CHECK(fx_card_matches(&c[2], "drm_rp1_dsi")); /* '-' and '_' alike */
    FX_CHECK(!fx_card_matches(&c[2], "drm-rp1-dpi"));
    FX_CHECK(!fx_card_matches(&c[2], "drm-rp1"));    /* no prefixes of driver names */
    FX_CHECK(fx_card_matches(&c[1], "vc4"));
    FX_CHECK(fx_card_matches(&c[1], "platform-axi:gpu"));
    FX_CHECK(fx_card_matches(&c[1], "platform-axi:gpu-card")); /* the udev link's name */
    FX_CHECK(!fx_card_matches(&c[1], "platform-axi"));
    /* the tail of a by-path name after a '-' names it too, never a middle */
    FX_CHECK(fx_card_matches(&c[2], "platform-1f00130000.dsi"));
    FX_CHECK(fx_card_matches(&c[2], "pci-0000:01:00.0-platform-1f00130000.dsi"));
    FX_CHECK(!fx_card_matches(&c[2], "pci-0000:01:00.0"));
    FX_CHECK(!fx_card_matches(&c[2], "1f00130000.dsi"));      /* a tail must start a component */
    FX_CHECK(!fx_card_matches(&c[1], "gpu"));
    FX_CHECK(!fx_card_matches(&c[2], ""));
    FX_CHECK(!fx_card_matches(&c[2], NULL));
    FX_CHECK(!fx_card_matches(&c[2], "/dev/fb0"));
}

FX_TEST(cards_pick_first_connected_across_cards)
{
    fx_card_desc c[3];
    int n = pi5(c), ci = -1, ki = -1;
    /* v3d has no KMS (error), vc4 nothing connected: the DSI panel */
    FX_CHECK_EQ(fx_card_pick_output(c, n, NULL, NULL, &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 2);
    FX_CHECK_EQ(ki, 0);
    /* plug HDMI-A-2 in: the first card in order with a connected output wins */
    c[1].conn[1].connected = 1;
    c[1].conn[1].modes = 30;
    FX_CHECK_EQ(fx_card_pick_output(c, n, NULL, NULL, &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
    FX_CHECK_EQ(ki, 1);
    /* a connector named alone is searched on every card */
    FX_CHECK_EQ(fx_card_pick_output(c, n, NULL, "DSI-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 2);
    /* a card named alone: its first connected output */
    FX_CHECK_EQ(fx_card_pick_output(c, n, "drm-rp1-dsi", NULL, &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 2);
    FX_CHECK_EQ(fx_card_pick_output(c, n, "vc4", "", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
    FX_CHECK_EQ(ki, 1);
}

FX_TEST(cards_pick_errors_say_which)
{
    fx_card_desc c[3];
    int n = pi5(c), ci = -1, ki = -1;
    FX_CHECK_EQ(fx_card_pick_output(c, n, "drm-rp1-dpi", NULL, &ci, &ki), FX_PICK_NO_CARD);
    FX_CHECK_EQ(fx_card_pick_output(c, n, NULL, "Composite-1", &ci, &ki), FX_PICK_NO_CONNECTOR);
    /* named, present, no modes: disconnected, and where */
    ci = ki = -1;
    FX_CHECK_EQ(fx_card_pick_output(c, n, NULL, "HDMI-A-1", &ci, &ki), FX_PICK_DISCONNECTED);
    FX_CHECK_EQ(ci, 1);
    FX_CHECK_EQ(ki, 0);
    /* DSI-1 exists, but not on the card asked for */
    FX_CHECK_EQ(fx_card_pick_output(c, n, "vc4", "DSI-1", &ci, &ki), FX_PICK_NO_CONNECTOR);
    FX_CHECK_EQ(fx_card_pick_output(c, n, NULL, "vc4:DSI-1", &ci, &ki), FX_PICK_NO_CONNECTOR);
    FX_CHECK_EQ(fx_card_pick_output(c, n, "vc4", NULL, &ci, &ki), FX_PICK_NONE_CONNECTED);
    /* a card that could not be read is never chosen, even by name */
    FX_CHECK_EQ(fx_card_pick_output(c, n, "v3d", NULL, &ci, &ki), FX_PICK_NO_CARD);
    FX_CHECK_EQ(fx_card_pick_output(c, 0, NULL, NULL, &ci, &ki), FX_PICK_NONE_CONNECTED);
    /* the card part and the device must agree */
    FX_CHECK_EQ(fx_card_pick_output(c, n, "vc4", "card2:DSI-1", &ci, &ki), FX_PICK_NO_CARD);
}

/* Pi 4: one vc4 card, HDMI-A-1, HDMI-A-2 and DSI-1 on it. */
FX_TEST(cards_pick_pi4_connector_on_one_card)
{
    fx_card_desc c[2];
    card(&c[0], 0, "v3d", "platform-fec00000.v3d");
    c[0].error = -19;
    card(&c[1], 1, "vc4", "platform-gpu");
    conn(&c[1], "HDMI-A-1", 1, 20);
    conn(&c[1], "HDMI-A-2", 1, 18);
    conn(&c[1], "DSI-1", 1, 1);
    int ci = -1, ki = -1;
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, NULL, &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ki, 0);
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "HDMI-A-2", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
    FX_CHECK_EQ(ki, 1);
    FX_CHECK_EQ(fx_card_pick_output(c, 2, "platform-gpu", "DSI-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ki, 2);
    /* forced on by video=HDMI-A-1:e: status unknown, modes present */
    c[1].conn[0].connected = -1;
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "HDMI-A-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ki, 0);
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, NULL, &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ki, 1); /* auto takes only "connected" */
}

/* Two cards with a Virtual-1 each: the first card wins unless qualified. */
FX_TEST(cards_pick_same_connector_name_on_two_cards)
{
    fx_card_desc c[2];
    card(&c[0], 0, "bochs-drm", "pci-0000:00:02.0");
    conn(&c[0], "Virtual-1", 1, 15);
    card(&c[1], 1, "virtio_gpu", "pci-0000:00:05.0");
    conn(&c[1], "Virtual-1", 1, 20);
    conn(&c[1], "Virtual-2", 0, 0);
    int ci = -1, ki = -1;
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "Virtual-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 0); /* the first card in order */
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "virtio-gpu:Virtual-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
    /* by-path names hold ':': the split is at the last one */
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "pci-0000:00:05.0:Virtual-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "card1:", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
    FX_CHECK_EQ(ki, 0);
    FX_CHECK_EQ(fx_card_pick_output(c, 2, "pci-0000:00:05.0", "Virtual-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "card1:Virtual-2", &ci, &ki), FX_PICK_DISCONNECTED);
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "card7:Virtual-1", &ci, &ki), FX_PICK_NO_CARD);
    /* the first card gone (error): the same name finds the second */
    c[0].error = -13;
    FX_CHECK_EQ(fx_card_pick_output(c, 2, NULL, "Virtual-1", &ci, &ki), FX_PICK_OK);
    FX_CHECK_EQ(ci, 1);
}
