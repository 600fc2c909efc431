/* mavframe.c - MAVLink 2 on the IR link through mavgen's generated C.
 *
 * Configuration of the generated headers for 1 KiB of SRAM:
 *  - the receive buffer holds the dialect's largest payload, not 255 bytes
 *    (MAVLINK_MAX_PAYLOAD_LEN; the parser refuses longer frames itself);
 *  - one channel whose status we own (MAVLINK_GET_CHANNEL_STATUS), used for
 *    the receive state and the transmit sequence number;
 *  - the CRC_EXTRA table stays in flash (MAVLINK_GET_MSG_ENTRY reads the
 *    generated MAVLINK_MESSAGE_CRCS from PROGMEM);
 *  - no signing (MAVLINK_NO_SIGN_PACKET, MAVLINK_NO_SIGNATURE_CHECK): see
 *    docs/protocol.md for what signing would cost.
 */
#include "mavframe.h"

#include <avr/pgmspace.h>
#include <string.h>

#include "mavlink/hexbot/version.h"
#define MAVLINK_MAX_PAYLOAD_LEN MAVLINK_MAX_DIALECT_PAYLOAD_SIZE
#define MAVLINK_COMM_NUM_BUFFERS 1
#define MAVLINK_NO_SIGN_PACKET
#define MAVLINK_NO_SIGNATURE_CHECK
#define MAVLINK_USE_CONVENIENCE_FUNCTIONS
#define MAVLINK_GET_CHANNEL_STATUS
#define MAVLINK_GET_MSG_ENTRY
#include "mavlink/mavlink_types.h"

#include "state.h"
#include "table.h"
#include "uart.h"

#define IR UART1

mavlink_system_t mavlink_system;
static mavlink_status_t status;
static mavlink_message_t rx;
static uint8_t crc_errors;

static mavlink_status_t *mavlink_get_channel_status(uint8_t chan)
{
    (void)chan;
    return &status;
}

/* Defined below, once the generated table is known. */
static const mavlink_msg_entry_t *mavlink_get_msg_entry(uint32_t msgid);

#define MAVLINK_SEND_UART_BYTES(chan, buf, len) uart_write(IR, (const uint8_t *)(buf), (uint8_t)(len))

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include "mavlink/hexbot/mavlink.h"
#pragma GCC diagnostic pop

/* main.c tells a MAVLink frame by its first byte without the generated headers */
_Static_assert(MAV_START == MAVLINK_STX, "MAV_START is not the generated MAVLINK_STX");

static const mavlink_msg_entry_t entries[] PROGMEM = MAVLINK_MESSAGE_CRCS;

static const mavlink_msg_entry_t *mavlink_get_msg_entry(uint32_t msgid)
{
    static mavlink_msg_entry_t found;
    for (uint8_t i = 0; i < sizeof entries / sizeof entries[0]; i++) {
        memcpy_P(&found, &entries[i], sizeof found);
        if (found.msgid == msgid)
            return &found;
    }
    return NULL;
}

uint8_t mav_busy(void)
{
    return status.parse_state > MAVLINK_PARSE_STATE_IDLE;
}

void mav_expire(tick_t last)
{
    if (mav_busy() && tick_since(last) > HB_PC_BYTE_TIMEOUT_TICKS)
        status.parse_state = MAVLINK_PARSE_STATE_IDLE;
}

tick_t mav_due(tick_t last, tick_t due)
{
    if (!mav_busy())
        return due;
    return tick_earlier(due, (tick_t)(last + HB_PC_BYTE_TIMEOUT_TICKS + 1u));
}

uint8_t mav_crc_errors(void)
{
    return crc_errors;
}

/* Argument bytes beyond the function's own are 'N' in a legacy frame;
 * MAVLink sends them as 0 so that the payload is truncated. Select's
 * further ids are optional: 0 there means none. */
static void legacy_args(uint8_t code, const uint8_t *in, uint8_t *out)
{
    uint8_t n = table_nargs(code);
    for (uint8_t k = 0; k < HB_PC_ARGS; k++)
        out[k] = (k < n && !(code == HB_FN_SELECT && k && !in[k])) ? in[k] : HB_UNUSED;
}

mav_result_t mav_push(uint8_t b, uint8_t *frame, uint8_t *target)
{
    uint8_t was_busy = mav_busy();
    /* rx itself holds the message once complete: no copy on the stack */
    uint8_t r = mavlink_frame_char_buffer(&rx, &status, b, NULL, NULL);
    if (r == MAVLINK_FRAMING_BAD_CRC) {
        if (crc_errors < 255u)
            crc_errors++;
        return MAV_DROPPED;
    }
    if (r != MAVLINK_FRAMING_OK) {
        if (mav_busy())
            return MAV_BUSY;
        return was_busy ? MAV_REJECTED : MAV_NONE;
    }
    if (rx.msgid != MAVLINK_MSG_ID_HEXBOT_COMMAND)
        return MAV_NONE; /* another message: not for a module */
    mavlink_hexbot_command_t cmd;
    mavlink_msg_hexbot_command_decode(&rx, &cmd);
    if (cmd.target_system && cmd.target_system != g_state.id)
        return MAV_NONE; /* another module's */
    frame[0] = HB_START;
    frame[1] = cmd.code;
    legacy_args(cmd.code, cmd.args, frame + 2);
    frame[HB_PC_FRAME_LEN - 1] = HB_END;
    *target = cmd.target_system;
    return MAV_COMMAND;
}

static void from_module(void)
{
    mavlink_system.sysid = g_state.id;
    mavlink_system.compid = HB_MAV_COMPONENT_COMM;
}

void mav_send_ack(uint8_t code, uint8_t legacy_ack)
{
    uint8_t result = legacy_ack == HB_TIMEOUT  ? HEXBOT_RESULT_CONTROL_TIMEOUT
                     : legacy_ack == HB_UNUSED ? HEXBOT_RESULT_UNUSED_CODE
                                               : HEXBOT_RESULT_DONE;
    from_module();
    mavlink_msg_hexbot_ack_send(MAVLINK_COMM_0, code, g_state.role, result, HB_ERR_NONE);
}

void mav_send_err(uint8_t code, uint8_t reason)
{
    from_module();
    mavlink_msg_hexbot_ack_send(MAVLINK_COMM_0, code, g_state.role, HEXBOT_RESULT_ERROR, reason);
}

void mav_send_status(void)
{
    from_module();
    mavlink_msg_hexbot_status_send(MAVLINK_COMM_0, HB_SCHEMA_HASH, g_state.role,
                                   g_state.localized, g_state.x, g_state.y, g_state.yref,
                                   g_state.last_error, crc_errors);
}

void mav_send_localized(void)
{
    from_module();
    mavlink_msg_hexbot_localized_send(MAVLINK_COMM_0, g_state.heard_side, g_state.yref,
                                      g_state.x, g_state.y);
}
