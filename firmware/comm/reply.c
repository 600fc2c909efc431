/* reply.c - replies to the PC: preamble, role prefix, ACK/ERR/STA. */
#include "reply.h"

#include <avr/pgmspace.h>

#include "comm_board.h"
#include "state.h"
#include "system.h"
#include "uart.h"
#include "version.h"

#define IR UART1

static poll_fn poll_hook;

void reply_init(poll_fn poll)
{
    poll_hook = poll;
}

void reply_wait_turn(uint8_t slots)
{
    tick_t delay;
    if (g_state.addressed)
        delay = (tick_t)g_state.rank * slots * HB_ACK_SLOT_TICKS;
    else if (g_state.role == HB_ROLE_SUBSTRATE)
        delay = slots > 1u ? (tick_t)slots * HB_ACK_SLOT_TICKS : HB_SUBSTRATE_ACK_DELAY_TICKS;
    else
        delay = 0;
    tick_t start = tick_now();
    while (tick_since(start) < delay) {
        poll_hook();
        sys_idle();
    }
}

void reply_dec2(uint8_t v)
{
    uart_putc(IR, (uint8_t)('0' + (v / 10u) % 10u));
    uart_putc(IR, (uint8_t)('0' + v % 10u));
}

void reply_preamble(void)
{
    comm_ir_select(IR_CENTRE);
    uart_puts_P(IR, PSTR("\n\r\n\r"));
}

static void prefix(void)
{
    reply_preamble();
    uart_putc(IR, g_state.role == HB_ROLE_SUBSTRATE ? 'S' : 'M');
    if (g_state.addressed)
        reply_dec2(g_state.id);
    uart_puts_P(IR, PSTR(": "));
}

static void eol(void)
{
    uart_putc(IR, '\n');
    uart_putc(IR, '\r');
}

void reply_line_P(const char *text)
{
    uart_puts_P(IR, text);
    eol();
}

void reply_tail(uint8_t with_id, uint8_t with_fw)
{
    if (with_id) {
        uart_puts_P(IR, PSTR(" ID="));
        reply_dec2(g_state.id);
    }
    if (with_fw)
        uart_puts_P(IR, PSTR(" FW=" HB_FW_VERSION));
}

void reply_ack_now(uint8_t code)
{
    prefix();
    uart_puts_P(IR, PSTR("ACK"));
    uart_putc(IR, code);
    eol();
}

void reply_err_now(uint8_t code, uint8_t reason)
{
    g_state.last_error = reason;
    prefix();
    uart_puts_P(IR, PSTR("ERR"));
    uart_putc(IR, code);
    uart_putc(IR, reason);
    eol();
}

void reply_ack(uint8_t code)
{
    reply_wait_turn(SLOTS_ACK);
    reply_ack_now(code);
}

void reply_err(uint8_t code, uint8_t reason)
{
    g_state.last_error = reason;
    reply_wait_turn(SLOTS_ACK);
    reply_err_now(code, reason);
}

void reply_status(void)
{
    reply_wait_turn(SLOTS_STATUS);
    prefix();
    uart_puts_P(IR, PSTR("STA"));
    uart_putc(IR, g_state.id);
    uart_putc(IR, g_state.role == HB_ROLE_SUBSTRATE ? 'S'
                  : g_state.role == HB_ROLE_MOBILE  ? 'M'
                                                    : '-');
    uart_putc(IR, g_state.localized);
    uart_putc(IR, (uint8_t)g_state.x);
    uart_putc(IR, (uint8_t)g_state.y);
    uart_putc(IR, g_state.yref);
    uart_putc(IR, g_state.last_error);
    eol();
}
