/* inbox.h - PC frames received but not yet run, oldest first.
 *
 * The communication board keeps reading the IR link while it waits (for
 * its reply slot, for the control board's echo, between the steps of a
 * sequence), so several frames can arrive before the main loop runs the
 * next one. They wait here, up to INBOX_FRAMES; a frame that arrives while
 * the inbox is full is dropped (the caller records HB_ERR_BUSY). One
 * producer and one consumer, both in the main loop: no interrupt touches it.
 */
#ifndef INBOX_H
#define INBOX_H

#include <stdint.h>

#include "hexbot_codes.h"
#include "system.h"

#define INBOX_FRAMES 4u

typedef struct {
    uint8_t frame[HB_PC_FRAME_LEN]; /* legacy layout '*' code args '#' */
    uint8_t framing;                /* FRAMING_LEGACY or FRAMING_MAVLINK */
    uint8_t target;                 /* MAVLink target_system: 0 = as Select says */
    tick_t received;                /* its last byte: a Localize's window starts here */
} inbox_entry_t;

/** Where the next frame is assembled; always free (not one of the kept). */
inbox_entry_t *inbox_slot(void);

/** Keep the frame assembled in inbox_slot(); 0 when the inbox was full and
 *  it was dropped. */
uint8_t inbox_keep(void);

/** Frames waiting. */
uint8_t inbox_count(void);

/** The @p k-th oldest waiting frame (k < inbox_count()). */
const inbox_entry_t *inbox_peek(uint8_t k);

/** Move the oldest frame to @p out; 0 when there is none. */
uint8_t inbox_take(inbox_entry_t *out);

/** Forget every waiting frame. */
void inbox_clear(void);

#endif /* INBOX_H */
