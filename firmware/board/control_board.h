/* control_board.h - the control board (Table 3-4): solenoid joints,
 * electromagnets (two drive lines per side) and the DIP switches. */
#ifndef CONTROL_BOARD_H
#define CONTROL_BOARD_H

#include <stdint.h>

/** Ports to their reset state: every joint closed, every magnet off. */
void control_board_init(void);

/** Joint j (1..6): open = solenoid energised (pin retracted). */
void control_joint(uint8_t joint, uint8_t open);
void control_joints_all(uint8_t open);

/** Magnet of side s (1..6): pole 0 positive, 1 negative; never both lines. */
void control_magnet_on(uint8_t side, uint8_t pole);
void control_magnet_off(uint8_t side);
void control_magnets_all_off(void);

/** Module id from the DIP switches PC0..PC7 (1..255; 0 = no switch on). */
uint8_t control_module_id(void);

#endif /* CONTROL_BOARD_H */
