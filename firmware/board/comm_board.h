/* comm_board.h - the communication board (Table 3-3, Table 3-5).
 *
 * LEDs are active low. Sides and joints are numbered 1..6 in the body
 * frame; callers pass valid numbers (the application checks ranges).
 */
#ifndef COMM_BOARD_H
#define COMM_BOARD_H

#include <stdint.h>

#define IR_CENTRE 0u /* IR channel 0 = centre transceiver (PC); 1..6 = side */

#define POLE_P 0u /* "(1)" LED of a side: positive magnet indication */
#define POLE_N 1u /* "(2)" LED of a side: negative magnet indication */

/** Ports to their reset state: every LED off, IR selector on the centre. */
void comm_board_init(void);

void comm_led_side(uint8_t side, uint8_t pole, uint8_t on);
void comm_led_joint(uint8_t joint, uint8_t on);

/** Route UART1 to IR channel @p ch (0 centre, 1..6 side); flushes first. */
void comm_ir_select(uint8_t ch);

/** The channel UART1 is routed to now. */
uint8_t comm_ir_channel(void);

#endif /* COMM_BOARD_H */
