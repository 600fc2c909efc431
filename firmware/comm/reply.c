/* reply.c - replies to the PC: preamble, role prefix, ACK/ERR/STA. */
#include "reply.h"

#include <avr/pgmspace.h>

#include "comm_board.h"
#include "id_text.h"
#include "image_mark.h"
#include "mavframe.h"
#include "state.h"
#include "system.h"
#include "uart.h"

#define IR UART1

static poll_fn poll_hook;
static due_fn due_hook;
/* The request being answered: its framing, whether it named this module
 * (MAVLink target_system = id: no Select, no slot) and its code. */
static uint8_t framing;
static uint8_t direct;
static uint8_t request_code;

void reply_init(poll_fn poll, due_fn due)
{
    poll_hook = poll;
    due_hook = due;
}

void reply_begin(uint8_t request_framing, uint8_t to_me, uint8_t code)
{
    framing = request_framing;
    direct = to_me;
    request_code = code;
}

uint8_t reply_direct(void)
{
    return direct;
}

void reply_wait_turn(uint8_t slots)
{
    tick_t delay;
    if (direct)
        delay = 0;
    else if (g_state.addressed)
        delay = (tick_t)g_state.rank * slots * HB_ACK_SLOT_TICKS;
    else if (g_state.role == HB_ROLE_SUBSTRATE)
        delay = slots > 1u ? (tick_t)slots * HB_ACK_SLOT_TICKS : HB_SUBSTRATE_ACK_DELAY_TICKS;
    else
        delay = 0;
    tick_t start = tick_now();
    tick_t waited;
    while ((waited = tick_since(start)) < delay) {
        uint8_t mark = sys_io_events;
        poll_hook();
        /* Rank 137 and up waits more than 32,767 ticks for a Localize slot,
         * which the idle's signed compare would take for a tick gone by:
         * sleep toward it in steps the compare can see. */
        tick_t step = (tick_t)(delay - waited) < SYS_IDLE_MAX_TICKS
                          ? delay : (tick_t)(waited + SYS_IDLE_MAX_TICKS);
        sys_idle_until(due_hook((tick_t)(start + step)), mark);
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
    uart_puts_P(IR, PSTR(HB_PREAMBLE));
}

static void prefix(void)
{
    reply_preamble();
    uart_putc(IR, g_state.role == HB_ROLE_SUBSTRATE ? HB_ROLE_LETTER_SUBSTRATE
                                                    : HB_ROLE_LETTER_MOBILE);
    if (g_state.addressed) {
        uint8_t digits[ID_TEXT_MAX];
        uart_write(IR, digits, id_text(digits, g_state.id));
    }
    uart_puts_P(IR, PSTR(": "));
}

static void eol(void)
{
    uart_puts_P(IR, PSTR(HB_EOL));
}

void reply_line_P(const char *text)
{
    uart_puts_P(IR, text);
    eol();
}

static uint8_t *text_P(uint8_t *p, const char *s)
{
    char c;
    while ((c = (char)pgm_read_byte(s++)) != 0)
        *p++ = (uint8_t)c;
    return p;
}

/* One boot line: text, optional " ID=nn" (nnn from 100), optional " FW=x", LF CR. */
static uint8_t *boot_line(uint8_t *p, const char *text, uint8_t with_id, uint8_t with_fw)
{
    p = text_P(p, text);
    if (with_id) {
        p = text_P(p, PSTR(HB_TEXT_ID_TAIL));
        p += id_text(p, g_state.id);
    }
    if (with_fw)
        p = text_P(p, PSTR(BOOT_FW_TAIL));
    return text_P(p, PSTR(HB_EOL));
}

uint8_t reply_boot_text(uint8_t *buf, uint8_t which)
{
    uint8_t *p = text_P(buf, PSTR(HB_PREAMBLE));
    if (which & BOOT_COMM_READY)
        p = boot_line(p, PSTR(HB_TEXT_COMM_READY), 0, 1);
    if (which & BOOT_CTR_READY)
        p = boot_line(p, PSTR(HB_TEXT_CTR_READY), 1, 0);
    if (which & BOOT_CTR_LISTENING)
        p = boot_line(p, PSTR(HB_TEXT_CTR_LISTENING), 0, 0);
    if (which & BOOT_COMM_LISTENING)
        p = boot_line(p, PSTR(HB_TEXT_COMM_LISTENING), 1, 1);
    return (uint8_t)(p - buf);
}

void reply_ack_now(uint8_t code)
{
    if (framing == FRAMING_MAVLINK) {
        comm_ir_select(IR_CENTRE);
        mav_send_ack(request_code, code);
        return;
    }
    prefix();
    uart_puts_P(IR, PSTR(HB_REPLY_ACK));
    uart_putc(IR, code);
    eol();
}

void reply_err_now(uint8_t code, uint8_t reason)
{
    g_state.last_error = reason;
    if (framing == FRAMING_MAVLINK) {
        comm_ir_select(IR_CENTRE);
        mav_send_err(code, reason);
        return;
    }
    prefix();
    uart_puts_P(IR, PSTR(HB_REPLY_ERR));
    uart_putc(IR, code);
    uart_putc(IR, reason);
    eol();
}

void reply_ack(uint8_t code)
{
    reply_wait_turn(HB_SLOTS_ACK);
    reply_ack_now(code);
}

void reply_err(uint8_t code, uint8_t reason)
{
    g_state.last_error = reason;
    reply_wait_turn(HB_SLOTS_ACK);
    reply_err_now(code, reason);
}

void reply_status(void)
{
    reply_wait_turn(HB_SLOTS_STATUS);
    if (framing == FRAMING_MAVLINK) {
        comm_ir_select(IR_CENTRE);
        mav_send_status();
        return;
    }
    prefix();
    uart_puts_P(IR, PSTR(HB_REPLY_STATUS));
    uart_putc(IR, g_state.id);
    uart_putc(IR, g_state.role == HB_ROLE_SUBSTRATE ? HB_ROLE_LETTER_SUBSTRATE
                  : g_state.role == HB_ROLE_MOBILE  ? HB_ROLE_LETTER_MOBILE
                                                    : HB_ROLE_LETTER_NONE);
    uart_putc(IR, g_state.localized);
    uart_putc(IR, (uint8_t)g_state.x);
    uart_putc(IR, (uint8_t)g_state.y);
    uart_putc(IR, g_state.yref);
    uart_putc(IR, g_state.last_error);
    uart_puts_P(IR, HB_IMAGE_MARK_SCHEMA); /* the protocol it was built from */
    eol();
}

void reply_localized(void)
{
    if (framing == FRAMING_MAVLINK) {
        comm_ir_select(IR_CENTRE);
        mav_send_localized();
        return;
    }
    reply_preamble();
    reply_line_P(PSTR(HB_TEXT_LOCALIZED));
    uart_puts_P(IR, PSTR(HB_LOC_SIDE));
    uart_putc(IR, (uint8_t)('0' + g_state.heard_side));
    uart_puts_P(IR, PSTR(HB_EOL HB_LOC_YREF));
    uart_putc(IR, (uint8_t)('0' + g_state.yref));
    uart_puts_P(IR, PSTR(HB_EOL HB_LOC_POS));
    int8_t c[2] = {g_state.x, g_state.y};
    for (uint8_t i = 0; i < 2; i++) {
        uart_putc(IR, c[i] < 0 ? '-' : '+');
        reply_dec2((uint8_t)(c[i] < 0 ? -c[i] : c[i]));
    }
    eol();
}
