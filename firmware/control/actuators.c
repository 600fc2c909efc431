/* actuators.c - the control board's functions (codes 1-24) on its joints
 * and magnets. Which function does what, the test walks and the Table 3-1
 * rotations are common/sequence.c, shared with the comm board's LED echo.
 */
#include "actuators.h"

#include "control_board.h"

_Static_assert(SEQ_POS == 0u && SEQ_NEG == 1u, "control_magnet_on(): 0 positive, 1 negative");

static const seq_outputs_t outputs = {
    control_joint, control_joints_all, control_magnet_on, control_magnet_off,
    control_magnets_all_off,
};

void actuators_init(wait_fn wait)
{
    seq_init(wait, actuators_off);
    actuators_off();
}

void actuators_off(void)
{
    control_magnets_all_off();
    control_joints_all(0);
}

void actuators_run(uint8_t code, const uint8_t *a)
{
    seq_run_function(&outputs, code, a);
}
