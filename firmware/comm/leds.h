/* leds.h - LED functions of Table 3-7 (codes 28-59) on the comm board.
 *
 * Sequences wait through the hook given to leds_init(); when it reports
 * that a new PC command arrived, the sequence stops and the LEDs go off.
 */
#ifndef LEDS_H
#define LEDS_H

#include <stdint.h>

#include "sequence.h"

void leds_init(wait_fn wait);
void leds_all(uint8_t on);
void leds_side_all(uint8_t pole, uint8_t on);
void leds_joint_all(uint8_t on);

/** Run LED function @p code with arguments a[0..3] (range-checked). */
void leds_run(uint8_t code, const uint8_t *a);

/** LED echo of a control-board function (what the thesis showed), as long
 *  as the function runs on the control board; 1 when the wait hook stopped
 *  it before its end. */
uint8_t leds_mirror(uint8_t code, const uint8_t *a);

#endif /* LEDS_H */
