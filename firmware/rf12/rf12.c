/* rf12.c - RF12 driver: the command words and packet format of the thesis'
 * wireless listing, with every wait on nIRQ bounded. */
#include "rf12.h"

#include <avr/wdt.h>

#include "hexbot_codes.h"
#include "rf12_board.h"
#include "system.h"

#define IRQ_TIMEOUT_TICKS 10u    /* a byte at 4.8 kbps takes 1.7 ms */
/* Wait this long for a packet to start: well inside the 2 s watchdog, which
 * wait_irq() feeds once per wait (the callers loop, each wait is bounded). */
#define PACKET_TIMEOUT_TICKS 150u

static const uint16_t init_words[] = {
    HB_RF12_CMD_CONFIG, /* 0x80D7: EL, EF, 433 MHz band, 12.0 pF */
    0x8239, /* !er, !ebb, ET, ES, EX, !eb, !ew, DC */
    HB_RF12_CMD_FREQ,   /* 0xA640: 434 MHz */
    HB_RF12_CMD_RATE,   /* 0xC647: 4.8 kbps */
    0x94A0, /* VDI, fast, 134 kHz, 0 dBm, -103 dBm */
    0xC2AC, /* AL, !ml, DIG, DQD4 */
    0xCA81, /* FIFO8, sync, !ff, DR */
    HB_RF12_CMD_SYNC,   /* 0xCED4: sync word 2D D4 */
    0xC483, /* @PWR, no restriction, !st, !fi, OE, EN */
    0x9850, /* !mp, 90 kHz, max output */
    0xCC67, /* PLL settings */
    0xE000, /* wake-up timer off */
    0xC800, /* low duty cycle off */
    0xC400, /* 1.66 MHz, 2.2 V */
};

void rf12_init(void)
{
    for (uint8_t i = 0; i < sizeof init_words / sizeof init_words[0]; i++)
        rf12_board_xfer(init_words[i]);
    /* Read the status: it clears the power-on interrupt, which otherwise
     * holds nIRQ low and makes the first receive read an empty FIFO. */
    rf12_board_xfer(0x0000);
}

/* Busy-wait (the listing's way): at 4.8 kbps a byte must be written every
 * 1.7 ms, and sleeping until the next 10 ms tick would let the transmit
 * register underrun. The tick interrupt still bounds the wait. */
static uint8_t wait_irq(tick_t ticks)
{
    wdt_reset();
    tick_t start = tick_now();
    while (!rf12_board_irq()) {
        if (tick_since(start) >= ticks)
            return 0;
    }
    return 1;
}

static uint8_t send_byte(uint8_t b)
{
    if (!wait_irq(IRQ_TIMEOUT_TICKS))
        return 0;
    rf12_board_xfer(0xB800u | b);
    return 1;
}

/* @p n bytes out; 0 at the first the radio did not take. */
static uint8_t send_bytes(const uint8_t *p, uint8_t n)
{
    for (uint8_t i = 0; i < n; i++)
        if (!send_byte(p[i]))
            return 0;
    return 1;
}

uint8_t rf12_send_packet(const uint8_t *data)
{
    static const uint8_t head[] = HB_RF12_HEAD;
    static const uint8_t trailer[] = HB_RF12_TRAILER;
    uint8_t sum = 0;
    for (uint8_t i = 0; i < RF12_PAYLOAD; i++)
        sum = (uint8_t)(sum + data[i]);
    rf12_board_xfer(0x0000);  /* read status: clears a pending interrupt */
    rf12_board_xfer(0x8239);  /* transmitter on */
    /* A radio that stops taking bytes (absent, stuck) ends the packet at
     * once: the rest would only wait out 25 more time-outs (2.5 s, past the
     * watchdog) for a packet nobody can decode. The trailer's dummy bytes
     * flush the shift register. */
    uint8_t ok = send_bytes(head, sizeof head) && send_bytes(data, RF12_PAYLOAD) &&
                 send_byte(sum) && send_bytes(trailer, sizeof trailer);
    rf12_board_xfer(0x8201);  /* transmitter off */
    return ok;
}

static int16_t recv_byte(tick_t ticks)
{
    if (!wait_irq(ticks))
        return -1;
    rf12_board_xfer(0x0000);
    return (int16_t)(rf12_board_xfer(0xB000) & 0xFFu); /* the listing wrote 0xB0000 */
}

void rf12_rx_arm(void)
{
    rf12_board_xfer(0x82D9);  /* receiver on */
    rf12_board_xfer(0xCA81);  /* FIFO reset: wait for the sync word again */
    rf12_board_xfer(0xCA83);  /* FIFO fill on sync */
    rf12_board_xfer(0x0000);  /* clear interrupts latched before (the init's
                                 transmitter underruns): nIRQ means data now */
}

uint8_t rf12_rx_ready(void)
{
    return rf12_board_irq();
}

int8_t rf12_rx_read(uint8_t *data, tick_t first_ticks)
{
    uint8_t sum = 0;
    int16_t b;
    for (uint8_t i = 0; i < RF12_PAYLOAD; i++) {
        b = recv_byte(i == 0 ? first_ticks : IRQ_TIMEOUT_TICKS);
        if (b < 0 && i == 0)
            goto fail;
        if (b < 0) {
            rf12_board_xfer(0xCA81);
            return RF12_RX_BAD_SUM; /* the packet stopped half-way */
        }
        data[i] = (uint8_t)b;
        sum = (uint8_t)(sum + (uint8_t)b);
    }
    b = recv_byte(IRQ_TIMEOUT_TICKS);
    rf12_board_xfer(0xCA81);
    return (b >= 0 && (uint8_t)b == sum) ? RF12_RX_OK : RF12_RX_BAD_SUM;
fail:
    rf12_board_xfer(0xCA81);
    return RF12_RX_NONE;
}

int8_t rf12_receive_packet(uint8_t *data)
{
    rf12_rx_arm();
    return rf12_rx_read(data, PACKET_TIMEOUT_TICKS);
}
