/* leds.c - status LED functions and sequences (Appendix A, comm board). */
#include "leds.h"

#include "comm_board.h"
#include "hexbot_codes.h"
#include "state.h"

static wait_fn wait_hook;

#define WAIT(t)                   \
    do {                          \
        if (wait_hook(t)) {       \
            leds_all(0);          \
            return;               \
        }                         \
    } while (0)

static uint8_t around(uint8_t i, int8_t k)
{
    int8_t v = (int8_t)((int8_t)i - 1 + k);
    while (v < 0)
        v += 6;
    while (v >= 6)
        v -= 6;
    return (uint8_t)(v + 1);
}

void leds_init(wait_fn wait)
{
    wait_hook = wait;
    leds_all(0);
}

void leds_side_all(uint8_t pole, uint8_t on)
{
    for (uint8_t s = 1; s <= 6; s++)
        comm_led_side(s, pole, on);
}

void leds_joint_all(uint8_t on)
{
    for (uint8_t j = 1; j <= 6; j++)
        comm_led_joint(j, on);
}

void leds_all(uint8_t on)
{
    leds_side_all(POLE_P, on);
    leds_side_all(POLE_N, on);
    leds_joint_all(on);
}

static void side_test(uint8_t n, uint8_t t, uint8_t pole)
{
    while (n--) {
        for (uint8_t i = 1; i <= 6; i++) {
            comm_led_side(i, pole, 1);
            WAIT(t);
            comm_led_side(i, pole, 0);
            WAIT(t);
        }
    }
}

static void joint_test(uint8_t n, uint8_t t)
{
    while (n--) {
        for (uint8_t i = 1; i <= 6; i++) {
            comm_led_joint(i, 1);
            WAIT(t);
            comm_led_joint(i, 0);
            WAIT(t);
        }
    }
}

/* Joint, side N and side P LEDs of each side in turn. The listing also
 * blinked the side's IR emitter with two bytes; we leave the IR link alone
 * (the bytes landed in the neighbour's receiver as noise). */
static void circle(uint8_t n, uint8_t t)
{
    while (n--) {
        for (uint8_t i = 1; i <= 6; i++) {
            comm_led_joint(i, 1);
            WAIT(t);
            comm_led_joint(i, 0);
            WAIT(t);
            comm_led_side(i, POLE_N, 1);
            WAIT(t);
            comm_led_side(i, POLE_N, 0);
            WAIT(t);
            comm_led_side(i, POLE_P, 1);
            WAIT(t);
            comm_led_side(i, POLE_P, 0);
            WAIT(t);
        }
    }
}

static void colour(uint8_t n, uint8_t t)
{
    while (n--) {
        leds_joint_all(1);
        WAIT(t);
        leds_joint_all(0);
        WAIT(t);
        leds_side_all(POLE_N, 1);
        WAIT(t);
        leds_side_all(POLE_N, 0);
        WAIT(t);
        leds_side_all(POLE_P, 1);
        WAIT(t);
        leds_side_all(POLE_P, 0);
        WAIT(t);
    }
}

static void flash1(uint8_t n, uint8_t t)
{
    while (n--) {
        leds_side_all(POLE_N, 1);
        leds_side_all(POLE_P, 0);
        WAIT(t);
        leds_side_all(POLE_N, 0);
        leds_side_all(POLE_P, 1);
        WAIT(t);
    }
    leds_all(0);
}

static void flash2(uint8_t n, uint8_t t)
{
    while (n--) {
        leds_all(1);
        WAIT(t);
        leds_all(0);
        WAIT(t);
    }
}

/* Show the global +Y direction (global side 2) on the body side facing it. */
static void show_yref(uint8_t dir)
{
    if (dir == 1)
        g_state.yref = around(g_state.yref + 1u, 1) - 1u;
    else if (dir == 2)
        g_state.yref = around(g_state.yref + 1u, -1) - 1u;
    uint8_t side = around(2, (int8_t)-(int8_t)g_state.yref);
    comm_led_side(side, POLE_P, 1);
    comm_led_side(side, POLE_N, 0);
    WAIT(10);
    comm_led_side(side, POLE_N, 1);
    comm_led_side(side, POLE_P, 0);
    WAIT(10);
    comm_led_side(side, POLE_N, 0);
}

static void rot_mobile_cw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    comm_led_joint(i, 1);
    comm_led_joint(around(i, 1), 1);
    WAIT(t1);
    comm_led_side(i, POLE_N, 1);
    comm_led_side(around(i, -1), POLE_N, 1);
    WAIT(t2);
    leds_joint_all(0);
    WAIT(t3);
    leds_all(0);
}

static void rot_mobile_ccw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    comm_led_joint(around(i, 1), 1);
    WAIT(t1);
    comm_led_side(i, POLE_N, 1);
    comm_led_side(around(i, -1), POLE_N, 1);
    WAIT(t2);
    comm_led_joint(i, 1);
    WAIT(t3);
    leds_all(0);
}

static void rot_substrate_cw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    comm_led_joint(around(i, -1), 1);
    WAIT(t1);
    comm_led_side(around(i, -3), POLE_N, 1);
    comm_led_side(around(i, -2), POLE_P, 1);
    WAIT(t2);
    comm_led_joint(around(i, -2), 1);
    WAIT(t3);
    leds_all(0);
}

static void rot_substrate_ccw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    comm_led_joint(around(i, -3), 1);
    comm_led_joint(around(i, -4), 1);
    WAIT(t1);
    comm_led_side(around(i, -4), POLE_N, 1);
    comm_led_side(around(i, -5), POLE_P, 1);
    WAIT(t2);
    leds_joint_all(0);
    WAIT(t3);
    leds_all(0);
}

void leds_run(uint8_t code, const uint8_t *a)
{
    switch (code) {
    case HB_FN_SIDE_ON_P: comm_led_side(a[0], POLE_P, 1); break;
    case HB_FN_SIDE_OFF_P: comm_led_side(a[0], POLE_P, 0); break;
    case HB_FN_SIDE_ON_ALL_P: leds_side_all(POLE_P, 1); break;
    case HB_FN_SIDE_OFF_ALL_P: leds_side_all(POLE_P, 0); break;
    case HB_FN_SIDE_ON_N: comm_led_side(a[0], POLE_N, 1); break;
    case HB_FN_SIDE_OFF_N: comm_led_side(a[0], POLE_N, 0); break;
    case HB_FN_SIDE_ON_ALL_N: leds_side_all(POLE_N, 1); break;
    case HB_FN_SIDE_OFF_ALL_N: leds_side_all(POLE_N, 0); break;
    case HB_FN_SIDE_PTEST: side_test(a[0], a[1], POLE_P); break;
    case HB_FN_SIDE_NTEST: side_test(a[0], a[1], POLE_N); break;
    case HB_FN_JOINT_ON: comm_led_joint(a[0], 1); break;
    case HB_FN_JOINT_OFF: comm_led_joint(a[0], 0); break;
    case HB_FN_JOINT_ON_ALL: leds_joint_all(1); break;
    case HB_FN_JOINT_OFF_ALL: leds_joint_all(0); break;
    case HB_FN_JOINT_TEST: joint_test(a[0], a[1]); break;
    case HB_FN_LON: leds_all(1); break;
    case HB_FN_LOFF: leds_all(0); break;
    case HB_FN_LCIRCLE: circle(a[0], a[1]); break;
    case HB_FN_LCOLOR: colour(a[0], a[1]); break;
    case HB_FN_LFLASH1: flash1(a[0], a[1]); break;
    case HB_FN_LFLASH2: flash2(a[0], a[1]); break;
    case HB_FN_LYREF: show_yref(a[0]); break;
    case HB_FN_LMCW: rot_mobile_cw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_LMCCW: rot_mobile_ccw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_LSCW: rot_substrate_cw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_LSCCW: rot_substrate_ccw(a[0], a[1], a[2], a[3]); break;
    default: break;
    }
}

void leds_mirror(uint8_t code, const uint8_t *a)
{
    switch (code) {
    case HB_FN_JX_OPEN: comm_led_joint(a[0], 1); break;
    case HB_FN_JX_CLOSE: comm_led_joint(a[0], 0); break;
    case HB_FN_JX_OPEN_ALL: leds_joint_all(1); break;
    case HB_FN_JX_CLOSE_ALL: leds_joint_all(0); break;
    case HB_FN_JTEST: joint_test(a[0], a[1]); break;
    case HB_FN_SX_P:
        comm_led_side(a[0], POLE_N, 0);
        comm_led_side(a[0], POLE_P, 1);
        break;
    case HB_FN_SX_N:
        comm_led_side(a[0], POLE_P, 0);
        comm_led_side(a[0], POLE_N, 1);
        break;
    case HB_FN_SX_OFF:
        comm_led_side(a[0], POLE_P, 0);
        comm_led_side(a[0], POLE_N, 0);
        break;
    case HB_FN_SX_OFF_ALL:
        leds_side_all(POLE_P, 0);
        leds_side_all(POLE_N, 0);
        break;
    case HB_FN_SPTEST: side_test(a[0], a[1], POLE_P); break;
    case HB_FN_SNTEST: side_test(a[0], a[1], POLE_N); break;
    case HB_FN_TURN_OFF_ALL: leds_all(0); break;
    case HB_FN_MCW: rot_mobile_cw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_MCCW: rot_mobile_ccw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_SCW: rot_substrate_cw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_SCCW: rot_substrate_ccw(a[0], a[1], a[2], a[3]); break;
    default: break;
    }
}
