/* main.c - wireless board test image (third listing of Appendix A).
 *
 * Power-on: green/red LEDs alternate three times (200 ms each), the radio
 * is configured, "RF12 READY" goes out on UART1 (4800 baud). Then, by the
 * mode jumper: TX test sends a packet with bytes 1..9 (rest 0) every
 * 400 ms, red LED blinking per packet; RX test waits for packets, green LED
 * blinking, and prints "START", the 16 bytes and 1/0 (sum matched) on UART1.
 * The listing named the two tests the other way round; we name them by what
 * they do.
 */
#include <avr/pgmspace.h>

#include "hexbot_codes.h"
#include "rf12.h"
#include "rf12_board.h"
#include "system.h"
#include "uart.h"
#include "version.h"

#define LED_TICKS 20u /* 200 ms */

static void power_on_leds(void)
{
    for (uint8_t i = 0; i < 3; i++) {
        rf12_board_led(RF12_LED_GREEN, 1);
        rf12_board_led(RF12_LED_RED, 0);
        sys_delay(LED_TICKS);
        rf12_board_led(RF12_LED_GREEN, 0);
        rf12_board_led(RF12_LED_RED, 1);
        sys_delay(LED_TICKS);
    }
    rf12_board_led(RF12_LED_GREEN, 0);
    rf12_board_led(RF12_LED_RED, 0);
}

static void tx_test(void)
{
    uint8_t data[RF12_PAYLOAD] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    for (;;) {
        rf12_board_led(RF12_LED_RED, 1);
        sys_delay(LED_TICKS);
        rf12_board_led(RF12_LED_RED, 0);
        rf12_send_packet(data);
        sys_delay(2u * LED_TICKS);
    }
}

static void rx_test(void)
{
    uint8_t data[RF12_PAYLOAD];
    for (;;) {
        rf12_board_led(RF12_LED_GREEN, 1);
        sys_delay(LED_TICKS);
        rf12_board_led(RF12_LED_GREEN, 0);
        int8_t r = rf12_receive_packet(data);
        if (r == RF12_RX_NONE)
            continue;
        uart_puts_P(UART1, PSTR(HB_TEXT_RF12_RX_START));
        uart_write(UART1, data, RF12_PAYLOAD);
        uart_putc(UART1, (uint8_t)r);
        uart_puts_P(UART1, PSTR(HB_EOL));
    }
}

int main(void)
{
    rf12_board_init();
    sys_init();
    uart_init(UART0, HB_UBRR_BOARD);
    uart_init(UART1, HB_UBRR_DEBUG);
    power_on_leds();
    rf12_init();
    uart_puts_P(UART1, PSTR(HB_PREAMBLE HB_TEXT_RF12_READY));
    uart_puts_P(UART1, rf12_board_tx_mode() ? PSTR(" MODE=TX") : PSTR(" MODE=RX"));
    uart_puts_P(UART1, PSTR(HB_TEXT_FW_TAIL HB_FW_VERSION HB_EOL));
    if (rf12_board_tx_mode())
        tx_test();
    rx_test();
    return 0;
}
