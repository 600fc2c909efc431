/* actuators.h - control-board functions of Table 3-7 (codes 1-24).
 *
 * Sequences wait in ticks through the wait hook given to actuators_init();
 * when the hook reports that a new command arrived, the sequence stops at
 * once and every actuator is switched off (the new command runs next).
 */
#ifndef ACTUATORS_H
#define ACTUATORS_H

#include <stdint.h>

#include "sequence.h"

void actuators_init(wait_fn wait);

/** Every joint closed, every magnet off. */
void actuators_off(void);

/** Run function @p code with arguments a[0..3] (already range-checked). */
void actuators_run(uint8_t code, const uint8_t *a);

#endif /* ACTUATORS_H */
