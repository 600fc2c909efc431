/* actuators.c - joints, magnets and the rotation sequences.
 *
 * Rotations follow the thesis listing (Appendix A, control board), which is
 * what drove the hardware; the one defect fixed is SCCW step 3, where the
 * listing drives both magnets negative while its comment and Table 3-1 say
 * S(i-4) negative, S(i-5) positive. Indices wrap around the hexagon
 * (joint 7 = joint 1): that is geometry, not input wrap-around; the
 * rotation joint itself is range-checked before we get here.
 */
#include "actuators.h"

#include "control_board.h"
#include "hexbot_codes.h"

#define POS 0u
#define NEG 1u

static wait_fn wait_hook;

/* Side/joint i + k around the hexagon, for i in 1..6 and k in -6..6. */
static uint8_t around(uint8_t i, int8_t k)
{
    int8_t v = (int8_t)((int8_t)i - 1 + k);
    while (v < 0)
        v += 6;
    while (v >= 6)
        v -= 6;
    return (uint8_t)(v + 1);
}

void actuators_init(wait_fn wait)
{
    wait_hook = wait;
    actuators_off();
}

void actuators_off(void)
{
    control_magnets_all_off();
    control_joints_all(0);
}

#define WAIT(t)                    \
    do {                           \
        if (wait_hook(t)) {        \
            actuators_off();       \
            return;                \
        }                          \
    } while (0)

static void joint_test(uint8_t n, uint8_t t)
{
    while (n--) {
        for (uint8_t i = 1; i <= 6; i++) {
            control_joint(i, 1);
            WAIT(t);
            control_joint(i, 0);
            WAIT(t);
        }
    }
}

static void magnet_test(uint8_t n, uint8_t t, uint8_t pole)
{
    while (n--) {
        for (uint8_t i = 1; i <= 6; i++) {
            control_magnet_on(i, pole);
            WAIT(t);
            control_magnet_off(i);
            WAIT(t);
        }
    }
}

/* Table 3-1 steps: 1 joints, 2 t1, 3 magnets, 4 t2, 5 joints, 6 t3, 7 joints, 8 magnets off. */
static void mobile_cw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    control_joint(i, 1);
    control_joint(around(i, 1), 1);
    WAIT(t1);
    control_magnet_on(i, NEG);
    control_magnet_on(around(i, -1), NEG);
    WAIT(t2);
    control_joints_all(0);
    WAIT(t3);
    control_magnets_all_off();
}

static void mobile_ccw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    control_joint(around(i, 1), 1);
    WAIT(t1);
    control_magnet_on(i, NEG);
    control_magnet_on(around(i, -1), NEG);
    WAIT(t2);
    control_joint(i, 1);
    WAIT(t3);
    control_joints_all(0);
    control_magnets_all_off();
}

static void substrate_cw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    control_joint(around(i, -1), 1);
    WAIT(t1);
    control_magnet_on(around(i, -3), NEG);
    control_magnet_on(around(i, -2), POS);
    WAIT(t2);
    control_joint(around(i, -2), 1);
    WAIT(t3);
    control_joints_all(0);
    control_magnets_all_off();
}

static void substrate_ccw(uint8_t i, uint8_t t1, uint8_t t2, uint8_t t3)
{
    control_joint(around(i, -3), 1);
    control_joint(around(i, -4), 1);
    WAIT(t1);
    control_magnet_on(around(i, -4), NEG);
    control_magnet_on(around(i, -5), POS);
    WAIT(t2);
    control_joints_all(0);
    WAIT(t3);
    control_magnets_all_off();
}

void actuators_run(uint8_t code, const uint8_t *a)
{
    switch (code) {
    case HB_FN_JX_OPEN: control_joint(a[0], 1); break;
    case HB_FN_JX_CLOSE: control_joint(a[0], 0); break;
    case HB_FN_JX_OPEN_ALL: control_joints_all(1); break;
    case HB_FN_JX_CLOSE_ALL: control_joints_all(0); break;
    case HB_FN_JTEST: joint_test(a[0], a[1]); break;
    case HB_FN_SX_P: control_magnet_on(a[0], POS); break;
    case HB_FN_SX_N: control_magnet_on(a[0], NEG); break;
    case HB_FN_SX_OFF: control_magnet_off(a[0]); break;
    case HB_FN_SX_OFF_ALL: control_magnets_all_off(); break;
    case HB_FN_SPTEST: magnet_test(a[0], a[1], POS); break;
    case HB_FN_SNTEST: magnet_test(a[0], a[1], NEG); break;
    case HB_FN_TURN_OFF_ALL: actuators_off(); break;
    case HB_FN_MCW: mobile_cw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_MCCW: mobile_ccw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_SCW: substrate_cw(a[0], a[1], a[2], a[3]); break;
    case HB_FN_SCCW: substrate_ccw(a[0], a[1], a[2], a[3]); break;
    default: break;
    }
}
