/* rf12_board.h - the wireless (RF12) board of Appendix A: bit-banged SPI to
 * the radio on PB4..PB7, its nIRQ line, two LEDs and a mode jumper. */
#ifndef RF12_BOARD_H
#define RF12_BOARD_H

#include <stdint.h>

#define RF12_LED_GREEN 0u
#define RF12_LED_RED 1u

void rf12_board_init(void);

/** Clock one 16-bit command word out (MSB first) and return what SDO said. */
uint16_t rf12_board_xfer(uint16_t word);

/** nIRQ is active low: 1 when the radio requests service. */
uint8_t rf12_board_irq(void);

void rf12_board_led(uint8_t led, uint8_t on);

/** Mode jumper on PA0 (pull-up): open = transmit test, closed = receive test. */
uint8_t rf12_board_tx_mode(void);

#endif /* RF12_BOARD_H */
