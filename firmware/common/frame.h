/* frame.h - receiver for the fixed-length '*' ... '#' frames.
 *
 * PC frames are '*' B1..B9 '#' (11 bytes), board frames '*' code a1..a4 '#'
 * (7 bytes). Argument bytes may be any value, '*' and '#' included, so the
 * receiver counts bytes instead of searching for '#'. When the last byte is
 * not '#' the frame is dropped and the receiver resynchronises on the next
 * '*' already received (so a truncated frame directly followed by a good
 * one still yields the good one); a frame that stops half-way is abandoned
 * after an inter-byte time-out.
 */
#ifndef FRAME_H
#define FRAME_H

#include <stdint.h>

#include "hexbot_codes.h"
#include "system.h"

#define FRAME_MAX HB_PC_FRAME_LEN /* the longest frame: the PC's */

typedef struct {
    uint8_t buf[FRAME_MAX];
    uint8_t len;      /* bytes collected, 0 = waiting for '*' */
    uint8_t size;     /* full frame length */
    tick_t last;      /* tick of the last byte, for the time-out */
    tick_t timeout;   /* inter-byte time-out in ticks */
} frame_rx_t;

typedef enum { FRAME_NONE = 0, FRAME_DONE, FRAME_DROPPED } frame_result_t;

void frame_init(frame_rx_t *f, uint8_t size, tick_t timeout);

/** Feed one byte. FRAME_DONE: buf holds a complete frame (read it before
 *  the next call). FRAME_DROPPED: a frame was just abandoned. */
frame_result_t frame_push(frame_rx_t *f, uint8_t b);

/** Take back the bytes buf[@p from..size-1] of the frame just completed as
 *  the start of the next frame (a caller that found the frame to be junk). */
void frame_resume(frame_rx_t *f, uint8_t from);

/** Abandon a half frame whose next byte is overdue; FRAME_DROPPED if so. */
frame_result_t frame_expire(frame_rx_t *f);

/** The earlier of @p due and the tick at which frame_expire() would abandon
 *  the half frame (for sys_idle_until()). */
tick_t frame_due(const frame_rx_t *f, tick_t due);

#endif /* FRAME_H */
