/* uart.c - interrupt-driven USART0/USART1 driver for the ATmega162.
 *
 * ATmega162 quirk: UBRRnH and UCSRnC share one I/O address; a write goes
 * to UCSRnC only when its URSELn bit is set. We write UBRRnH first (URSEL
 * clear), then UCSRnC with URSEL set.
 */
#include "uart.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>

#include "ring.h"

typedef struct {
    ring_t rx;
    ring_t tx;
    volatile uint8_t sent; /* a byte has been loaded since boot: TXC means something */
} uart_state_t;

static uart_state_t port[2];

/* A byte at 300 baud takes 3.3 ticks: a transmitter that has not freed a
 * slot within this many ticks is stuck, and the byte is dropped. */
#define TX_STALL_TICKS 20u
/* Longest a flush may take: a full ring at 300 baud is 107 ms; allow the
 * rest of the ring plus the shift register with margin. */
#define FLUSH_MAX_TICKS 150u

void uart_init(uint8_t u, uint16_t ubrr)
{
    if (u == UART0) {
        UCSR0B = 0;
        UCSR0A = 0;
        UBRR0H = (uint8_t)(ubrr >> 8); /* URSEL0 clear: UBRR0H */
        UBRR0L = (uint8_t)ubrr;
        UCSR0C = (1 << URSEL0) | (1 << UCSZ01) | (1 << UCSZ00); /* 8N1 */
        UCSR0B = (1 << RXCIE0) | (1 << RXEN0) | (1 << TXEN0);
    } else {
        UCSR1B = 0;
        UCSR1A = 0;
        UBRR1H = (uint8_t)(ubrr >> 8);
        UBRR1L = (uint8_t)ubrr;
        UCSR1C = (1 << URSEL1) | (1 << UCSZ11) | (1 << UCSZ10);
        UCSR1B = (1 << RXCIE1) | (1 << RXEN1) | (1 << TXEN1);
    }
}

/* A byte with a framing or overrun error (collision, noise) is dropped: the
 * frame it belonged to then fails its length or end-byte check. */
static inline void rx_store(uart_state_t *s, uint8_t status, uint8_t b, uint8_t err_mask)
{
    if (!(status & err_mask))
        ring_put(&s->rx, b);
    sys_io_events++; /* wake sys_idle_until() */
}

ISR(USART0_RXC_vect)
{
    uint8_t status = UCSR0A; /* read the error flags before UDR */
    uint8_t b = UDR0;
    rx_store(&port[0], status, b, (1 << FE0) | (1 << DOR0));
}

ISR(USART1_RXC_vect)
{
    uint8_t status = UCSR1A;
    uint8_t b = UDR1;
    rx_store(&port[1], status, b, (1 << FE1) | (1 << DOR1));
}

ISR(USART0_UDRE_vect)
{
    int16_t b = ring_get(&port[0].tx);
    if (b < 0) {
        UCSR0B &= (uint8_t)~(1 << UDRIE0);
        return;
    }
    UCSR0A = (1 << TXC0); /* clear "transmit complete" for this byte */
    UDR0 = (uint8_t)b;
    port[0].sent = 1;
    sys_io_events++; /* a slot freed: wake sys_idle_until() (uart_putc waits for it) */
}

ISR(USART1_UDRE_vect)
{
    int16_t b = ring_get(&port[1].tx);
    if (b < 0) {
        UCSR1B &= (uint8_t)~(1 << UDRIE1);
        return;
    }
    UCSR1A = (1 << TXC1);
    UDR1 = (uint8_t)b;
    port[1].sent = 1;
    sys_io_events++;
}

int16_t uart_getc(uint8_t u)
{
    return ring_get(&port[u & 1u].rx);
}

int16_t uart_getc_wait(uint8_t u, tick_t ticks)
{
    tick_t start = tick_now();
    for (;;) {
        uint8_t mark = sys_io_events;
        int16_t b = uart_getc(u);
        if (b >= 0)
            return b;
        if (tick_since(start) >= ticks)
            return -1;
        sys_idle_until(start + ticks, mark);
    }
}

void uart_rx_clear(uint8_t u)
{
    ring_clear(&port[u & 1u].rx);
}

static inline void tx_kick(uint8_t u)
{
    if (u == UART0)
        UCSR0B |= (1 << UDRIE0);
    else
        UCSR1B |= (1 << UDRIE1);
}

uint8_t uart_try_putc(uint8_t u, uint8_t b)
{
    uint8_t queued = ring_put(&port[u & 1u].tx, b);
    tx_kick(u);
    return queued;
}

void uart_putc(uint8_t u, uint8_t b)
{
    tick_t start = tick_now();
    for (;;) {
        uint8_t mark = sys_io_events;
        if (uart_try_putc(u, b))
            return;
        if (tick_since(start) >= TX_STALL_TICKS)
            return; /* transmitter stuck: drop rather than hang */
        sys_idle_until(start + TX_STALL_TICKS, mark);
    }
}

void uart_write(uint8_t u, const uint8_t *p, uint8_t n)
{
    while (n--)
        uart_putc(u, *p++);
}

void uart_puts_P(uint8_t u, const char *p)
{
    char c;
    while ((c = (char)pgm_read_byte(p++)) != 0)
        uart_putc(u, (uint8_t)c);
}

static uint8_t tx_idle(uint8_t u)
{
    if (ring_count(&port[u & 1u].tx))
        return 0;
    if (!port[u & 1u].sent)
        return 1;
    if (u == UART0)
        return !(UCSR0B & (1 << UDRIE0)) && (UCSR0A & (1 << UDRE0)) &&
               (UCSR0A & (1 << TXC0));
    return !(UCSR1B & (1 << UDRIE1)) && (UCSR1A & (1 << UDRE1)) && (UCSR1A & (1 << TXC1));
}

/* TXC raises no interrupt here: look at it on every tick. */
void uart_flush(uint8_t u)
{
    tick_t start = tick_now();
    while (!tx_idle(u) && tick_since(start) < FLUSH_MAX_TICKS)
        sys_idle();
}
