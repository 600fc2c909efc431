/* main.c - wireless board as the module's radio link (our addition; the
 * thesis planned it for "the next stage").
 *
 * The board's USART0 joins the comm board's IR multiplexer on the centre
 * input (protocol/pins.py, RF12_LINK_*), so the comm board takes radio
 * bytes as PC bytes and its replies on the centre come back here. The
 * bridge is transparent both ways:
 *   air -> comm board: a packet whose sum matched gives its link bytes
 *       (payload byte 0 = how many follow, at most HB_RF12_LINK_BYTES) to
 *       USART0; a bad packet is dropped, as the IR drops a garbled frame;
 *   comm board -> air: bytes from USART0 go out in one packet when
 *       HB_RF12_LINK_BYTES are waiting or the line has been quiet for two
 *       byte times (the end of a reply).
 * The receiver stays armed between packets; the board transmits only what
 * the comm board sent, so it is half duplex like the IR.
 * Green LED: a packet received; red: transmitting. UART1 is the debug
 * port: one boot line.
 */
#include <avr/pgmspace.h>
#include <avr/wdt.h>

#include "hexbot_codes.h"
#include "../rf12/rf12.h"
#include "pins.h"
#include "rf12_board.h"
#include "system.h"
#include "uart.h"
#include "version.h"

#define LINK HB_RF12_LINK_UART
#define LINK_QUIET_TICKS HB_IR_TICKS(2) /* a reply has ended */

static uint8_t out[RF12_PAYLOAD]; /* length byte + link bytes to send */

static void air_to_link(void)
{
    uint8_t in[RF12_PAYLOAD];
    rf12_board_led(RF12_LED_GREEN, 1);
    /* nIRQ: the first byte is in the FIFO already */
    if (rf12_rx_read(in, 1u) == RF12_RX_OK && in[0] <= HB_RF12_LINK_BYTES)
        uart_write(LINK, in + 1, in[0]);
    rf12_board_led(RF12_LED_GREEN, 0);
    rf12_rx_arm();
}

static void link_to_air(void)
{
    for (uint8_t i = (uint8_t)(out[0] + 1u); i < RF12_PAYLOAD; i++)
        out[i] = 0;
    rf12_board_led(RF12_LED_RED, 1);
    rf12_send_packet(out);
    rf12_board_led(RF12_LED_RED, 0);
    out[0] = 0;
    rf12_rx_arm();
}

int main(void)
{
    rf12_board_init();
    sys_init();
    uart_init(LINK, HB_UBRR_IR);
    uart_init(UART1, HB_UBRR_DEBUG);
    rf12_init();
    rf12_rx_arm();
    uart_puts_P(UART1, PSTR(HB_PREAMBLE HB_TEXT_RF12_LINK_READY HB_TEXT_FW_TAIL HB_FW_VERSION
                            HB_EOL));
    tick_t last = tick_now();
    for (;;) {
        /* Busy, never asleep: nIRQ is no interrupt pin, and the two-byte FIFO
         * must be read within ~3 ms once a packet starts. */
        wdt_reset();
        if (rf12_rx_ready())
            air_to_link();
        int16_t b;
        while (out[0] < HB_RF12_LINK_BYTES && (b = uart_getc(LINK)) >= 0) {
            out[++out[0]] = (uint8_t)b;
            last = tick_now();
        }
        if (out[0] == HB_RF12_LINK_BYTES ||
            (out[0] && tick_since(last) >= LINK_QUIET_TICKS))
            link_to_air();
    }
}
