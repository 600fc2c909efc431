/* reply.h - what the communication board sends the PC on the IR centre
 * channel, and when.
 *
 * Schedule: legacy mode (no Select since boot) answers at once as mobile
 * and after 1 s as substrate (thesis). Addressed mode answers after
 * rank x slots x HB_ACK_SLOT_TICKS, where "slots" is how many slots the
 * reply kind needs on the 300-baud link (HB_SLOTS_ACK for ACK/ERR,
 * HB_SLOTS_STATUS, HB_SLOTS_LOCALIZE), so that replies of modules answering the
 * same broadcast never overlap.
 */
#ifndef REPLY_H
#define REPLY_H

#include <stdint.h>

#include "hexbot_codes.h"
#include "system.h"
#include "version.h"

/* Boot texts (reply_boot_text), in the thesis' order; one bit each. */
#define BOOT_COMM_READY 0x01u     /* "COMM. BOARD READY FW=x" */
#define BOOT_CTR_READY 0x02u      /* "CTR. BOARD READY ID=nn" (nnn from 100) */
#define BOOT_CTR_LISTENING 0x04u  /* "CTR. LISTENING" */
#define BOOT_COMM_LISTENING 0x08u /* "COMM. LISTENING ID=nn FW=x" */
#define BOOT_FW_TAIL HB_TEXT_FW_TAIL HB_FW_VERSION
#define TEXT_LEN(s) (sizeof(s) - 1u)
/* The most a module sends once its id is known: preamble, then three lines
 * with a three-digit id (the protocol counts them without the version:
 * HB_BOOT_TEXT_FIXED_BYTES); ids below 100 send two bytes less. */
#define REPLY_BYTES_BOOT (HB_BOOT_TEXT_FIXED_BYTES + TEXT_LEN(HB_FW_VERSION))
_Static_assert(REPLY_BYTES_BOOT ==
                   TEXT_LEN(HB_PREAMBLE) + TEXT_LEN(HB_TEXT_CTR_READY HB_TEXT_ID_TAIL "nnn" HB_EOL) +
                       TEXT_LEN(HB_TEXT_CTR_LISTENING HB_EOL) +
                       TEXT_LEN(HB_TEXT_COMM_LISTENING HB_TEXT_ID_TAIL "nnn" BOOT_FW_TAIL HB_EOL),
               "boot text and HB_BOOT_TEXT_FIXED_BYTES disagree");

typedef uint8_t (*poll_fn)(void);

/* Framing of a request, and so of its replies */
#define FRAMING_LEGACY 0u  /* '*' B1..B9 '#', text replies */
#define FRAMING_MAVLINK 1u /* MAVLink 2 HEXBOT_COMMAND, HEXBOT_* replies */

/** Answer the request with @p code in @p request_framing from now on;
 *  @p to_me: a MAVLink target_system naming this module (answer at once,
 *  whatever the Select state). Boot texts stay legacy. */
void reply_begin(uint8_t request_framing, uint8_t to_me, uint8_t code);

/** The request named this module (no Select needed). */
uint8_t reply_direct(void);

/** @p poll keeps input moving while a reply waits for its slot; @p due
 *  names the ticks at which it has something to do without new input. */
void reply_init(poll_fn poll, due_fn due);

/** Wait for this module's turn for a reply needing @p slots slots. */
void reply_wait_turn(uint8_t slots);

/** Preamble on the centre channel (no prefix). */
void reply_preamble(void);

/** ACK + code, in the ACK slot. */
void reply_ack(uint8_t code);

/** ERR + code + reason, in the ACK slot; records the error. */
void reply_err(uint8_t code, uint8_t reason);

/** STA reply, in the status slot. */
void reply_status(void);

/** The localization report (LOCALIZED, Side, Yref, Pos / HEXBOT_LOCALIZED). */
void reply_localized(void);

/** A text line from flash (no preamble), LF CR appended. */
void reply_line_P(const char *text);

/** Write the boot texts chosen by @p which (BOOT_* bits) after a preamble
 * into @p buf (REPLY_BYTES_BOOT bytes at least); returns their length.
 * Built in RAM so that the caller can feed them to the IR transmitter while
 * the LEDs run. */
uint8_t reply_boot_text(uint8_t *buf, uint8_t which);

/** Ack/err/status body helpers for callers that waited already. */
void reply_ack_now(uint8_t code);
void reply_err_now(uint8_t code, uint8_t reason);

/** Two decimal digits. */
void reply_dec2(uint8_t v);

#endif /* REPLY_H */
