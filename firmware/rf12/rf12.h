/* rf12.h - RF12 radio driver (433 MHz, 4.8 kbps FSK) over bit-banged SPI. */
#ifndef RF12_H
#define RF12_H

#include <stdint.h>

#define RF12_PAYLOAD 16u

/** Send the configuration words of the listing. */
void rf12_init(void);

/** One packet: 3 x AA preamble, sync 2D D4, 16 bytes, 8-bit sum, 3 x AA.
 *  Returns 0 if the radio stopped asking for bytes (time-out). */
uint8_t rf12_send_packet(const uint8_t *data);

#define RF12_RX_OK 1
#define RF12_RX_BAD_SUM 0
#define RF12_RX_NONE (-1)

/** Receive one packet through the FIFO: RF12_RX_OK, RF12_RX_BAD_SUM, or
 *  RF12_RX_NONE when no packet started within 2 s. */
int8_t rf12_receive_packet(uint8_t *data);

#endif /* RF12_H */
