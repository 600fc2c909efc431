/* mavframe.h - MAVLink 2 framing on the IR link (dialect protocol/hexbot.xml,
 * C from pymavlink's mavgen in include/mavlink/, no codec of our own).
 *
 * A frame starts with 0xFD where a legacy frame starts with '*': the
 * receiver routes each byte to one parser or the other by that first
 * byte. A HEXBOT_COMMAND whose checksum (with CRC_EXTRA) fails is dropped
 * and counted, never executed. Replies to a MAVLink request go out as
 * MAVLink messages from system id = module id, with sequence numbers.
 */
#ifndef MAVFRAME_H
#define MAVFRAME_H

#include <stdint.h>

#include "hexbot_codes.h"
#include "system.h"

#define MAV_START 0xFDu /* MAVLINK_STX of wire protocol 2.0 */

typedef enum { MAV_NONE = 0, MAV_BUSY, MAV_COMMAND, MAV_DROPPED, MAV_REJECTED } mav_result_t;

/** A MAVLink frame is being received (bytes belong to mav_push). */
uint8_t mav_busy(void);

/** Feed one byte. MAV_COMMAND: a command for this module (or for all)
 *  is in @p frame as a legacy frame '*' code args '#' (the unused argument
 *  bytes restored to 'N'), with its target in @p target. MAV_DROPPED: a
 *  frame failed its checksum and was counted. MAV_REJECTED: the header
 *  turned out not to be MAVLink's at this byte (a stray 0xFD before a
 *  legacy frame): the byte is the caller's to use. */
mav_result_t mav_push(uint8_t b, uint8_t *frame, uint8_t *target);

/** Abandon a half frame whose next byte is overdue (last byte at @p last). */
void mav_expire(tick_t last);

/** The earlier of @p due and the tick mav_expire(@p last) would drop a
 *  half-parsed frame at (for sys_idle_until()). */
tick_t mav_due(tick_t last, tick_t due);

/** Frames dropped for a bad checksum since boot (saturates at 255). */
uint8_t mav_crc_errors(void);

/** Replies; the module's state (id, role, position) from g_state.
 *  HEXBOT_ACK for command @p code: @p legacy_ack is what a legacy ACK would
 *  carry (the code, HB_UNUSED or HB_TIMEOUT). */
void mav_send_ack(uint8_t code, uint8_t legacy_ack);
/** HEXBOT_ACK with result ERROR and @p reason. */
void mav_send_err(uint8_t code, uint8_t reason);
void mav_send_status(void);
void mav_send_localized(void);

#endif /* MAVFRAME_H */
