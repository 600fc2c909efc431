/* leds.c - status LED functions and sequences (Appendix A, comm board).
 *
 * The walks and the rotation echoes are the patterns of common/sequence.c,
 * the ones the control board runs on its joints and magnets: here they drive
 * the LEDs that show them (joint LED = joint open, side LED of a pole =
 * magnet on with that pole).
 */
#include "leds.h"

#include "comm_board.h"
#include "hexbot_codes.h"
#include "state.h"

_Static_assert(POLE_P == SEQ_POS && POLE_N == SEQ_NEG, "side LED poles are magnet poles");

#define WAIT SEQ_WAIT

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

static void all_off(void)
{
    leds_all(0);
}

void leds_init(wait_fn wait)
{
    seq_init(wait, all_off);
    leds_all(0);
}

/* Outputs for the walks: one LED, or a whole group (i ignored). */
static void side_p(uint8_t i, uint8_t on) { comm_led_side(i, POLE_P, on); }
static void side_n(uint8_t i, uint8_t on) { comm_led_side(i, POLE_N, on); }
static void joints(uint8_t i, uint8_t on) { (void)i; leds_joint_all(on); }
static void sides_p(uint8_t i, uint8_t on) { (void)i; leds_side_all(POLE_P, on); }
static void sides_n(uint8_t i, uint8_t on) { (void)i; leds_side_all(POLE_N, on); }
static void all(uint8_t i, uint8_t on) { (void)i; leds_all(on); }

static const set_fn joint_walk[] = {comm_led_joint};
static const set_fn p_walk[] = {side_p};
static const set_fn n_walk[] = {side_n};
/* LCircle: joint, side N and side P LEDs of each side in turn. The listing
 * also blinked the side's IR emitter with two bytes; we leave the IR link
 * alone (the bytes landed in the neighbour's receiver as noise). */
static const set_fn circle_walk[] = {comm_led_joint, side_n, side_p};
/* LColor: every joint LED, every N LED, every P LED. */
static const set_fn colour_walk[] = {joints, sides_n, sides_p};
static const set_fn flash2_walk[] = {all};

/* The control functions as LEDs: joint LED = joint open, the side LED of a
 * pole = magnet on with that pole. */
static void magnet(uint8_t side, uint8_t pole)
{
    comm_led_side(side, pole ^ 1u, 0);
    comm_led_side(side, pole, 1);
}

static void magnet_off(uint8_t side)
{
    comm_led_side(side, POLE_P, 0);
    comm_led_side(side, POLE_N, 0);
}

static void magnets_off(void)
{
    leds_side_all(POLE_P, 0);
    leds_side_all(POLE_N, 0);
}

static const seq_outputs_t outputs = {comm_led_joint, leds_joint_all, magnet, magnet_off,
                                      magnets_off};

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

/* Show the global +Y direction (global side 2) on the body side facing it. */
static void show_yref(uint8_t dir)
{
    if (dir == 1)
        g_state.yref = seq_around(g_state.yref + 1u, 1) - 1u;
    else if (dir == 2)
        g_state.yref = seq_around(g_state.yref + 1u, -1) - 1u;
    uint8_t side = seq_around(2, (int8_t)-(int8_t)g_state.yref);
    comm_led_side(side, POLE_P, 1);
    comm_led_side(side, POLE_N, 0);
    WAIT(HB_YREF_BLINK_TICKS);
    comm_led_side(side, POLE_N, 1);
    comm_led_side(side, POLE_P, 0);
    WAIT(HB_YREF_BLINK_TICKS);
    comm_led_side(side, POLE_N, 0);
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
    case HB_FN_SIDE_PTEST: seq_walk(a[0], a[1], 6, p_walk, 1); break;
    case HB_FN_SIDE_NTEST: seq_walk(a[0], a[1], 6, n_walk, 1); break;
    case HB_FN_JOINT_ON: comm_led_joint(a[0], 1); break;
    case HB_FN_JOINT_OFF: comm_led_joint(a[0], 0); break;
    case HB_FN_JOINT_ON_ALL: leds_joint_all(1); break;
    case HB_FN_JOINT_OFF_ALL: leds_joint_all(0); break;
    case HB_FN_JOINT_TEST: seq_walk(a[0], a[1], 6, joint_walk, 1); break;
    case HB_FN_LON: leds_all(1); break;
    case HB_FN_LOFF: leds_all(0); break;
    case HB_FN_LCIRCLE: seq_walk(a[0], a[1], 6, circle_walk, 3); break;
    case HB_FN_LCOLOR: seq_walk(a[0], a[1], 1, colour_walk, 3); break;
    case HB_FN_LFLASH1: flash1(a[0], a[1]); break;
    case HB_FN_LFLASH2: seq_walk(a[0], a[1], 1, flash2_walk, 1); break;
    case HB_FN_LYREF: show_yref(a[0]); break;
    case HB_FN_LMCW: seq_rotation(&outputs, SEQ_MCW, a); break;
    case HB_FN_LMCCW: seq_rotation(&outputs, SEQ_MCCW, a); break;
    case HB_FN_LSCW: seq_rotation(&outputs, SEQ_SCW, a); break;
    case HB_FN_LSCCW: seq_rotation(&outputs, SEQ_SCCW, a); break;
    default: break;
    }
}

uint8_t leds_mirror(uint8_t code, const uint8_t *a)
{
    seq_take_stopped();
    seq_run_function(&outputs, code, a);
    return seq_take_stopped();
}
