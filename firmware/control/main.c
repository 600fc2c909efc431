/* main.c - control board: handshake with the communication board, then
 * execute the board frames it forwards (UART0) or that arrive on the debug
 * port (UART1), echoing each code and logging it on the debug port.
 *
 * States: BOOT (self-test, "CTR. BOARD READY") -> HANDSHAKE ('R' id every
 * 100 ms until the comm board answers 'R', at most 5 s) -> LISTENING
 * (answer a late 'R' with 'L' id; run frames). A frame that arrives while
 * a sequence runs stops it, switches every actuator off and runs next. Every
 * error path (a dropped or invalid frame) switches every actuator off.
 */
#include <avr/pgmspace.h>
#include <string.h>

#include "actuators.h"
#include "control_board.h"
#include "frame.h"
#include "hexbot_codes.h"
#include "id_text.h"
#include "system.h"
#include "table.h"
#include "uart.h"
#include "version.h"


#define SRC_COMM UART0
#define SRC_DEBUG UART1

static frame_rx_t rx[2];
static uint8_t pending[HB_BOARD_FRAME_LEN];
static uint8_t pending_src;
static uint8_t have_pending;
static uint8_t module_id;

static void debug_line_P(const char *text)
{
    uart_puts_P(SRC_DEBUG, text);
    uart_puts_P(SRC_DEBUG, PSTR(HB_EOL));
}

static void debug_preamble(void)
{
    uart_puts_P(SRC_DEBUG, PSTR(HB_PREAMBLE));
}

static void send_link(uint8_t what)
{
    uart_putc(SRC_COMM, what);
    uart_putc(SRC_COMM, module_id);
}

/* Move received bytes into the frame receivers; 1 when a frame is pending. */
static uint8_t poll_links(void)
{
    for (uint8_t src = 0; src < 2; src++) {
        int16_t b;
        while ((b = uart_getc(src)) >= 0) {
            if (src == SRC_COMM && rx[src].len == 0 && b == HB_LINK_READY) {
                /* The comm board (re)started: what we run, nobody asked for
                 * any more (and its LEDs no longer show it). */
                actuators_off();
                send_link(HB_LINK_LISTENING);
                continue;
            }
            frame_result_t r = frame_push(&rx[src], (uint8_t)b);
            if (r == FRAME_DONE) {
                memcpy(pending, rx[src].buf, sizeof pending);
                pending_src = src;
                have_pending = 1;
            } else if (r == FRAME_DROPPED) {
                actuators_off(); /* error path: a broken command may have been a stop */
            }
        }
        if (frame_expire(&rx[src]) == FRAME_DROPPED)
            actuators_off();
    }
    return have_pending;
}

/* The earlier of @p due and the tick a half frame of poll_links() expires. */
static tick_t links_due(tick_t due)
{
    return frame_due(&rx[0], frame_due(&rx[1], due));
}

/* Sequence delay that gives way to a newly arrived command. */
static uint8_t wait_or_abort(tick_t n)
{
    return sys_delay_polling(n, poll_links, links_due);
}

static void run_pending(void)
{
    uint8_t code = pending[1];
    const uint8_t *args = &pending[2];
    uint8_t ok = table_board(code) == HB_BOARD_CONTROL && table_args_ok(code, args, HB_BOARD_ARGS);
    uint8_t echo = ok ? code : HB_UNUSED;
    have_pending = 0;

    if (pending_src == SRC_COMM)
        uart_putc(SRC_COMM, echo); /* the acknowledgement the comm board waits for */
    debug_preamble();
    uart_puts_P(SRC_DEBUG, PSTR(HB_REPLY_ACK));
    uart_putc(SRC_DEBUG, echo);
    uart_puts_P(SRC_DEBUG, PSTR(HB_EOL HB_REPLY_MSG));
    uart_write(SRC_DEBUG, &pending[1], 1 + HB_BOARD_ARGS);
    uart_puts_P(SRC_DEBUG, PSTR(HB_EOL));
    if (ok)
        actuators_run(code, args);
    else
        actuators_off(); /* error path: a command we cannot run leaves nothing on */
}

static uint8_t handshake(void)
{
    for (uint8_t tries = 0; tries < HB_HANDSHAKE_MAX_TRIES; tries++) {
        send_link(HB_LINK_READY);
        tick_t start = tick_now();
        while (tick_since(start) < HB_HANDSHAKE_RETRY_TICKS) {
            uint8_t mark = sys_io_events;
            int16_t b = uart_getc(SRC_COMM);
            if (b == HB_LINK_READY)
                return 1;
            if (b < 0)
                sys_idle_until(start + HB_HANDSHAKE_RETRY_TICKS, mark);
        }
    }
    return 0;
}

static void put_id_tail(void)
{
    uint8_t digits[ID_TEXT_MAX];
    uart_puts_P(SRC_DEBUG, PSTR(HB_TEXT_ID_TAIL));
    uart_write(SRC_DEBUG, digits, id_text(digits, module_id));
    uart_puts_P(SRC_DEBUG, PSTR(HB_TEXT_FW_TAIL HB_FW_VERSION));
}

int main(void)
{
    control_board_init(); /* every actuator off before anything else */
    sys_init();
    uart_init(UART0, HB_UBRR_BOARD);
    uart_init(UART1, HB_UBRR_DEBUG);
    frame_init(&rx[0], HB_BOARD_FRAME_LEN, HB_BOARD_BYTE_TIMEOUT_TICKS);
    frame_init(&rx[1], HB_BOARD_FRAME_LEN, HB_BOARD_BYTE_TIMEOUT_TICKS);
    actuators_init(wait_or_abort);

    sys_delay(10); /* supplies settle */
    module_id = control_module_id();
    /* Self-test: each joint opens for 50 ms in turn (the thesis' JTest(1,5)). */
    for (uint8_t j = 1; j <= 6; j++) {
        control_joint(j, 1);
        sys_delay(5);
        control_joint(j, 0);
        sys_delay(5);
    }

    debug_preamble();
    uart_puts_P(SRC_DEBUG, PSTR(HB_TEXT_CTR_READY));
    put_id_tail();
    uart_puts_P(SRC_DEBUG, PSTR(HB_EOL));
    if (handshake())
        debug_line_P(PSTR(HB_TEXT_COMM_READY));
    send_link(HB_LINK_LISTENING);
    debug_line_P(PSTR(HB_TEXT_CTR_LISTENING));

    /* Idle: sleep through the ticks until a byte comes or a half frame
     * expires (docs/firmware.md, "The idle path"). */
    for (;;) {
        uint8_t mark = sys_io_events;
        if (poll_links())
            run_pending();
        else
            sys_idle_until(links_due(tick_now() + SYS_IDLE_MAX_TICKS), mark);
    }
}
