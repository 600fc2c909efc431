/* Cost of MAVLink 2 signing on the comm board: mavgen's signature check on a
 * HEXBOT_COMMAND, between two PORTA writes that m162run time-stamps. */
#include <avr/io.h>
#include <string.h>
#include "mavlink/hexbot/version.h"
#define MAVLINK_MAX_PAYLOAD_LEN MAVLINK_MAX_DIALECT_PAYLOAD_SIZE
#define MAVLINK_COMM_NUM_BUFFERS 1
#include "mavlink/mavlink_types.h"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include "mavlink/hexbot/mavlink.h"

mavlink_signing_t signing;
mavlink_signing_streams_t streams;
mavlink_message_t msg;

int main(void)
{
    DDRA = 0xFF;
    uint8_t args[8] = {3};
    mavlink_msg_hexbot_command_pack(255, 190, &msg, 1, 1, args);
    msg.incompat_flags = MAVLINK_IFLAG_SIGNED;
    for (uint8_t i = 0; i < 32; i++)
        signing.secret_key[i] = i;
    PORTA = 1;
    volatile bool ok = mavlink_signature_check(&signing, &streams, &msg);
    PORTA = 2;
    (void)ok;
    for (;;) {}
}
