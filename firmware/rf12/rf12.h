/* rf12.h - RF12 radio driver (433 MHz, 4.8 kbps FSK) over bit-banged SPI. */
#ifndef RF12_H
#define RF12_H

#include <stdint.h>

#include "hexbot_codes.h"
#include "system.h"

#define RF12_PAYLOAD HB_RF12_PAYLOAD

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

/* The same in steps, for a caller with other work between packets: arm the
 * receiver (FIFO filled from the next sync word on), poll nIRQ, read. */
void rf12_rx_arm(void);
uint8_t rf12_rx_ready(void);
/** Read one armed packet, the first byte within @p first_ticks; disarms. */
int8_t rf12_rx_read(uint8_t *data, tick_t first_ticks);

#endif /* RF12_H */
