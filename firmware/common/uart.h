/* uart.h - both USARTs of the ATmega162, interrupt driven.
 *
 * Receive and transmit each go through a 32-byte ring: the RXC interrupt
 * only stores bytes (dropping those with a framing or overrun error, which
 * are what collisions and noise produce), the UDRE interrupt only sends
 * them. Every wait is bounded: uart_getc_wait() has a time-out, uart_putc()
 * gives up (and drops the byte) when the transmitter makes no progress.
 */
#ifndef UART_H
#define UART_H

#include <stdint.h>

#include "system.h"

#define UART0 0u
#define UART1 1u

/** 8N1 with divisor @p ubrr (the generated HB_UBRR_*), receiver and
 *  transmitter on. */
void uart_init(uint8_t u, uint16_t ubrr);

/** Next received byte, or -1 if none is waiting. */
int16_t uart_getc(uint8_t u);

/** Next received byte within @p ticks, or -1 on time-out. */
int16_t uart_getc_wait(uint8_t u, tick_t ticks);

/** Discard every received byte not yet read. */
void uart_rx_clear(uint8_t u);

/** Queue one byte if the ring has room; 0 (nothing queued) if it is full. */
uint8_t uart_try_putc(uint8_t u, uint8_t b);

/** Queue one byte for transmission (waits, bounded, for room). */
void uart_putc(uint8_t u, uint8_t b);

/** Queue @p n bytes. */
void uart_write(uint8_t u, const uint8_t *p, uint8_t n);

/** Queue a string from flash. */
void uart_puts_P(uint8_t u, const char *p);

/** Wait (bounded) until every queued byte has left the shift register. */
void uart_flush(uint8_t u);

#endif /* UART_H */
