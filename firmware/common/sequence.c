/* sequence.c - timed patterns: test walks and Table 3-1 rotations.
 *
 * Rotations follow the thesis listing (Appendix A, control board), which is
 * what drove the hardware; the one defect fixed is SCCW step 3, where the
 * listing drives both magnets negative while its comment and Table 3-1 say
 * S(i-4) negative, S(i-5) positive. Indices wrap around the hexagon
 * (joint 7 = joint 1): that is geometry, not input wrap-around; the
 * rotation joint itself is range-checked before we get here.
 */
#include "sequence.h"

#include <avr/pgmspace.h>

#include "hexbot_codes.h"

static wait_fn wait_hook;
static void (*stop_hook)(void);
static uint8_t stopped; /* a pattern stopped since seq_take_stopped() */

#define WAIT SEQ_WAIT

void seq_init(wait_fn wait, void (*stop)(void))
{
    wait_hook = wait;
    stop_hook = stop;
}

uint8_t seq_wait(tick_t ticks)
{
    if (!wait_hook(ticks))
        return 0;
    stop_hook();
    stopped = 1;
    return 1;
}

uint8_t seq_take_stopped(void)
{
    uint8_t was = stopped;
    stopped = 0;
    return was;
}

uint8_t seq_around(uint8_t i, int8_t k)
{
    int8_t v = (int8_t)((int8_t)i - 1 + k);
    while (v < 0)
        v += 6;
    while (v >= 6)
        v -= 6;
    return (uint8_t)(v + 1);
}

void seq_walk(uint8_t n, uint8_t t, uint8_t last, const set_fn *sets, uint8_t nsets)
{
    while (n--) {
        for (uint8_t i = 1; i <= last; i++) {
            for (uint8_t k = 0; k < nsets; k++) {
                sets[k](i, 1);
                WAIT(t);
                sets[k](i, 0);
                WAIT(t);
            }
        }
    }
}

/* Table 3-1 as offsets from the rotation joint i. Steps: 1 open joints,
 * 2 t1, 3 magnets, 4 t2, 5 open one joint or close all, 6 t3, 7-8 close
 * all joints and switch the magnets off (stop()). */
#define NO_JOINT 0x7F  /* step 1: only one joint */
#define CLOSE_ALL 0x7F /* step 5: close every joint instead */

typedef struct {
    int8_t open[2];      /* step 1 */
    int8_t magnet[2];    /* step 3: the first negative... */
    uint8_t second_pole; /* ...the second of this pole */
    int8_t step5;
} rotation_steps_t;

static const rotation_steps_t steps[4] PROGMEM = {
    [SEQ_MCW] = {{0, 1}, {0, -1}, SEQ_NEG, CLOSE_ALL},
    [SEQ_MCCW] = {{1, NO_JOINT}, {0, -1}, SEQ_NEG, 0},
    [SEQ_SCW] = {{-1, NO_JOINT}, {-3, -2}, SEQ_POS, -2},
    [SEQ_SCCW] = {{-3, -4}, {-4, -5}, SEQ_POS, CLOSE_ALL},
};

void seq_rotation(const seq_outputs_t *out, seq_rotation_t r, const uint8_t *a)
{
    rotation_steps_t s;
    uint8_t i = a[0];
    memcpy_P(&s, &steps[r], sizeof s);
    out->joint(seq_around(i, s.open[0]), 1);
    if (s.open[1] != NO_JOINT)
        out->joint(seq_around(i, s.open[1]), 1);
    WAIT(a[1]);
    out->magnet(seq_around(i, s.magnet[0]), SEQ_NEG);
    out->magnet(seq_around(i, s.magnet[1]), s.second_pole);
    WAIT(a[2]);
    if (s.step5 == CLOSE_ALL)
        out->joints(0);
    else
        out->joint(seq_around(i, s.step5), 1);
    WAIT(a[3]);
    stop_hook();
}

/* SPTest/SNTest walk the magnets of one pole: seq_walk() outputs take no
 * pole, so the walk reads it from here. */
static const seq_outputs_t *walk_out;
static uint8_t walk_pole;

static void walk_magnet(uint8_t side, uint8_t on)
{
    if (on)
        walk_out->magnet(side, walk_pole);
    else
        walk_out->magnet_off(side);
}

static const set_fn magnet_walk[] = {walk_magnet};

static void magnet_test(const seq_outputs_t *out, uint8_t pole, const uint8_t *a)
{
    walk_out = out;
    walk_pole = pole;
    seq_walk(a[0], a[1], 6, magnet_walk, 1);
}

void seq_run_function(const seq_outputs_t *out, uint8_t code, const uint8_t *a)
{
    switch (code) {
    case HB_FN_JX_OPEN: out->joint(a[0], 1); break;
    case HB_FN_JX_CLOSE: out->joint(a[0], 0); break;
    case HB_FN_JX_OPEN_ALL: out->joints(1); break;
    case HB_FN_JX_CLOSE_ALL: out->joints(0); break;
    case HB_FN_JTEST: seq_walk(a[0], a[1], 6, &out->joint, 1); break;
    case HB_FN_SX_P: out->magnet(a[0], SEQ_POS); break;
    case HB_FN_SX_N: out->magnet(a[0], SEQ_NEG); break;
    case HB_FN_SX_OFF: out->magnet_off(a[0]); break;
    case HB_FN_SX_OFF_ALL: out->magnets_off(); break;
    case HB_FN_SPTEST: magnet_test(out, SEQ_POS, a); break;
    case HB_FN_SNTEST: magnet_test(out, SEQ_NEG, a); break;
    case HB_FN_TURN_OFF_ALL: stop_hook(); break;
    case HB_FN_MCW: seq_rotation(out, SEQ_MCW, a); break;
    case HB_FN_MCCW: seq_rotation(out, SEQ_MCCW, a); break;
    case HB_FN_SCW: seq_rotation(out, SEQ_SCW, a); break;
    case HB_FN_SCCW: seq_rotation(out, SEQ_SCCW, a); break;
    default: break;
    }
}
