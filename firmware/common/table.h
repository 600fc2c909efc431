/* table.h - the function table of hexbot_codes.h, as the firmware uses it. */
#ifndef TABLE_H
#define TABLE_H

#include <stdint.h>

/** HB_BOARD_CONTROL / HB_BOARD_COMM, or HB_BOARD_NONE for unused codes. */
uint8_t table_board(uint8_t code);

/** 1 when every argument of @p code is within its documented range and
 *  the frame's other argument bytes, up to @p slots, are the 'N' filler.
 *  Select's optional ids (args 2..8) are the caller's business. */
uint8_t table_args_ok(uint8_t code, const uint8_t *args, uint8_t slots);

/** How many argument bytes @p code uses (0 for unused codes). */
uint8_t table_nargs(uint8_t code);

#endif /* TABLE_H */
