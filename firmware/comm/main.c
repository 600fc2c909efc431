/* main.c - communication board: the module's link to the PC (IR, UART1 at
 * 300 baud) and to its control board (UART0 at 4800 baud).
 *
 * States: BOOT ("COMM. BOARD READY") -> HANDSHAKE (control 'R' id -> answer
 * 'R' until 'L' id; bounded, a missing control board only makes control
 * functions answer '~') -> LISTENING: PC frames are dispatched by the
 * function table of hexbot_codes.h; control-board functions are forwarded
 * and acknowledged with the control board's echo. The board sleeps between
 * interrupts; every wait is bounded.
 */
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <string.h>

#include "comm_board.h"
#include "frame.h"
#include "hexbot_codes.h"
#include "inbox.h"
#include "leds.h"
#include "localize.h"
#include "mavframe.h"
#include "reply.h"
#include "state.h"
#include "system.h"
#include "table.h"
#include "uart.h"

#define IR UART1
#define CTRL UART0

/* Handshake timing (protocol/timing.py): a control board that booted with
 * us says 'R' after its 0.7 s self-test; past HB_HANDSHAKE_PROBE_TICKS it
 * is already listening (only we restarted) and we ask. */

/* Boot slots: every module of a cluster boots at once and the PC hears them
 * all on one IR medium, so the texts that carry the id go out in the
 * module's own slot: rank (id - 1) mod HB_BOOT_SLOTS, the first slot at
 * HB_BOOT_FIRST_SLOT_TICKS after reset (the handshake and LFlash1/2 are over
 * by 1.7 s), each slot as long as the slot text at 300 baud plus a guard. */
#define BOOT_SLOT_TICKS HB_BOOT_SLOT_TICKS(REPLY_BYTES_BOOT)
_Static_assert(REPLY_BYTES_BOOT < 200u, "version string too long for the boot text");

module_state_t g_state;

static frame_rx_t pc_rx;
static tick_t last_ir_byte;
static uint8_t control_ready; /* 'R' seen from the control board */
static uint8_t booted;        /* past the boot handshake: a new 'R' is a restart */
static uint8_t mirroring;     /* a control function's LED echo is running */
static uint8_t off_unechoed;  /* a TurnOffAll went out whose echo may still come */
static const uint8_t *boot_next; /* boot text still to queue (see boot_texts) */
static uint8_t boot_left;

/* --- links ---------------------------------------------------------------- */

/* 'R' id or 'L' id from the control board, outside command exchanges. */
static void link_byte(uint8_t b)
{
    if (b != HB_LINK_READY && b != HB_LINK_LISTENING)
        return;
    int16_t id = uart_getc_wait(CTRL, HB_LINK_ID_TICKS);
    if (id >= 0) /* any byte is an id: 8 DIP switches */
        g_state.id = (uint8_t)id;
    if (b == HB_LINK_READY) {
        control_ready = 1;
        g_state.control_up = 0;
        if (booted) /* reset or brown-out: its magnets and joints dropped */
            g_state.last_error = HB_ERR_CONTROL_RESTARTED;
        uart_putc(CTRL, HB_LINK_READY);
    } else {
        g_state.control_up = 1;
    }
}

/* A stray '*' eight bytes before a frame whose code is '#' (35, SideOffAllN)
 * makes "*" + 8 bytes + "*#" a complete frame, and the real one is lost.
 * A complete frame that ends in "*#" and that we would refuse anyway
 * (unknown code, argument out of range, a filler byte that is not 'N')
 * is taken for that: its "*#" starts
 * the next frame. A frame we would execute is executed. */
static uint8_t junk_before_hash_code(const uint8_t *f)
{
    return f[HB_PC_FRAME_LEN - 2] == HB_START &&
           (table_board(f[1]) == HB_BOARD_NONE || !table_args_ok(f[1], f + 2, HB_PC_ARGS));
}

/* The frame assembled in the inbox slot waits its turn (or is dropped). */
static void keep_frame(uint8_t framing, uint8_t target)
{
    inbox_entry_t *e = inbox_slot();
    e->framing = framing;
    e->target = target;
    e->received = last_ir_byte;
    if (!inbox_keep())
        g_state.last_error = HB_ERR_BUSY;
}

/* A MAVLink byte (the frame began with 0xFD): a command for us goes to
 * the inbox, in legacy layout. 0 when the byte was not MAVLink's
 * after all (the header broke on it): it may start a legacy frame. */
static uint8_t mav_byte(uint8_t b)
{
    uint8_t target;
    mav_result_t r = mav_push(b, inbox_slot()->frame, &target);
    if (r == MAV_COMMAND) {
        keep_frame(FRAMING_MAVLINK, target);
    } else if (r == MAV_DROPPED) {
        g_state.last_error = HB_ERR_BAD_FRAME;
    }
    return r != MAV_REJECTED;
}

/* Keep the IR link moving: boot text out, PC frames in (to the inbox). */
static void poll_ir(void)
{
    int16_t b;
    while (boot_left && uart_try_putc(IR, *boot_next)) {
        boot_next++;
        boot_left--;
    }
    if (frame_expire(&pc_rx) == FRAME_DROPPED)
        g_state.last_error = HB_ERR_BAD_FRAME;
    mav_expire(last_ir_byte);
    while ((b = uart_getc(IR)) >= 0) {
        last_ir_byte = tick_now();
        /* Framing by the first byte: 0xFD starts MAVLink, '*' legacy. */
        if (pc_rx.len == 0 && (mav_busy() || b == MAV_START) && mav_byte((uint8_t)b))
            continue;
        frame_result_t r = frame_push(&pc_rx, (uint8_t)b);
        if (r == FRAME_DONE && junk_before_hash_code(pc_rx.buf)) {
            frame_resume(&pc_rx, HB_PC_FRAME_LEN - 2);
            g_state.last_error = HB_ERR_BAD_FRAME;
        } else if (r == FRAME_DONE) {
            memcpy(inbox_slot()->frame, pc_rx.buf, HB_PC_FRAME_LEN);
            keep_frame(FRAMING_LEGACY, 0);
        } else if (r == FRAME_DROPPED) {
            g_state.last_error = HB_ERR_BAD_FRAME;
        }
    }
}

/* The earlier of @p due and the next tick at which poll_ir() (and so
 * poll_inputs()) has something to do without a new byte: a half frame's
 * time-out. Sending the boot text waits for transmit slots, which wake
 * sys_idle_until() as bytes do. */
static tick_t ir_due(tick_t due)
{
    return mav_due(last_ir_byte, frame_due(&pc_rx, due));
}

/* Keep both links moving; 1 when a PC frame waits in the inbox. */
static uint8_t poll_inputs(void)
{
    int16_t b;
    poll_ir();
    while ((b = uart_getc(CTRL)) >= 0) {
        if (b == HB_FN_TURN_OFF_ALL)
            off_unechoed = 0; /* the late echo of control_off(0) */
        else
            link_byte((uint8_t)b);
    }
    return inbox_count() != 0;
}

/* A frame that would drive the control board. */
static uint8_t drives_control(uint8_t code)
{
    return table_board(code) == HB_BOARD_CONTROL || code == HB_FN_CW || code == HB_FN_CCW;
}

/* While a control function runs, only a frame that drives the control board
 * stops it (whoever it is addressed to: control_off() makes the stop real);
 * a Status or an LED function waits in the inbox until it has ended. */
static uint8_t poll_control_stop(void)
{
    uint8_t n = poll_inputs();
    for (uint8_t k = 0; n && k < inbox_count(); k++)
        if (drives_control(inbox_peek(k)->frame[1]))
            return 1;
    return 0;
}

/* Sequence delay that gives way to a new PC command. */
static uint8_t wait_or_abort(tick_t n)
{
    return sys_delay_polling(n, mirroring ? poll_control_stop : poll_inputs, ir_due);
}

static void send_board_frame(uint8_t code, const uint8_t *a)
{
    uart_putc(CTRL, HB_START);
    uart_putc(CTRL, code);
    uart_write(CTRL, a, HB_BOARD_ARGS);
    uart_putc(CTRL, HB_END);
}

/* Forward a control-board function; returns the echo, HB_TIMEOUT, or the
 * wrong byte the control board answered. The IR link is read meanwhile
 * (its 31-byte ring holds less than a second at 300 baud): frames that
 * arrive go to the inbox and run after this one. */
static uint8_t forward(uint8_t code, const uint8_t *a)
{
    send_board_frame(code, a);
    tick_t start = tick_now();
    while (tick_since(start) < HB_CONTROL_ACK_TIMEOUT_TICKS) {
        uint8_t mark = sys_io_events;
        poll_ir();
        int16_t b = uart_getc(CTRL);
        if (b < 0) {
            sys_idle_until(ir_due((tick_t)(start + HB_CONTROL_ACK_TIMEOUT_TICKS)), mark);
            continue;
        }
        if (b == code) {
            if (code == HB_FN_TURN_OFF_ALL)
                off_unechoed = 0;
            return code;
        }
        if (off_unechoed && b == HB_FN_TURN_OFF_ALL) {
            off_unechoed = 0;
            continue;
        }
        if (b == HB_LINK_READY || b == HB_LINK_LISTENING) {
            link_byte((uint8_t)b); /* the control board restarted meanwhile */
            continue;
        }
        return (uint8_t)b;
    }
    return HB_TIMEOUT;
}

/* --- functions ------------------------------------------------------------ */

/* Every actuator off on the control board: after a broken exchange, what it
 * runs is unknown. @p wait_echo 0 when it did not answer at all: the frame
 * goes out, and its late echo is dropped (forward(), poll_inputs()). */
static void control_off(uint8_t wait_echo)
{
    /* the filler, as every board frame has it: the control board refuses
     * other bytes where a function takes no argument */
    static const uint8_t none[HB_BOARD_ARGS] = {HB_UNUSED, HB_UNUSED, HB_UNUSED, HB_UNUSED};
    if (wait_echo) {
        forward(HB_FN_TURN_OFF_ALL, none);
    } else {
        send_board_frame(HB_FN_TURN_OFF_ALL, none);
        off_unechoed = 1;
    }
}

/* Function @p run on the control board for the PC's @p code; the LED echo
 * lasts as long as it runs, and the ACK says it ran to its end. A control
 * frame that arrives meanwhile stops it: ERR STOPPED, never ACK. @p moves:
 * this module's cell changes (it is no longer localized). */
static void drive_control(uint8_t code, uint8_t run, const uint8_t *args, uint8_t moves)
{
    uint8_t echo = forward(run, args);
    if (echo == HB_TIMEOUT) {
        g_state.last_error = HB_ERR_CONTROL_TIMEOUT;
        reply_ack(HB_TIMEOUT); /* the thesis' '~' */
        control_off(0);
        return;
    }
    if (echo != run) {
        control_off(1);
        reply_err(code, HB_ERR_CONTROL_MISMATCH);
        return;
    }
    if (moves && !g_state.reference)
        g_state.localized = 0; /* the mobile module moved, or began to */
    mirroring = 1;
    uint8_t stopped = leds_mirror(run, args);
    mirroring = 0;
    if (stopped) {
        control_off(1);
        reply_err(code, HB_ERR_STOPPED);
        return;
    }
    reply_ack(code);
}

static void control_function(uint8_t code, const uint8_t *a)
{
    drive_control(code, code, a, code == HB_FN_MCW || code == HB_FN_MCCW);
}

/* 67/68: the substrate runs SCW/SCCW(si..), the mobile MCW/MCCW(mi..). */
static void combined_rotation(uint8_t code, const uint8_t *a)
{
    uint8_t cw = code == HB_FN_CW;
    uint8_t sub = g_state.role == HB_ROLE_SUBSTRATE;
    uint8_t run = sub ? (cw ? HB_FN_SCW : HB_FN_SCCW) : (cw ? HB_FN_MCW : HB_FN_MCCW);
    const uint8_t *args = sub ? a : a + 4;
    if (g_state.role == HB_ROLE_NONE) {
        reply_err(code, HB_ERR_NO_ROLE);
        return;
    }
    drive_control(code, run, args, !sub);
}

static void localize(uint8_t code, tick_t started)
{
    loc_result_t r = localize_run(started);
    reply_wait_turn(HB_SLOTS_LOCALIZE);
    if (r == LOC_NOT_HEARD) {
        reply_err_now(code, HB_ERR_NOT_HEARD);
        return;
    }
    if (r == LOC_LEARNED)
        reply_localized();
    reply_ack_now(code);
}

static void select_modules(const uint8_t *a)
{
    if (a[0] > HB_MAX_SELECT_ID) {
        g_state.last_error = HB_ERR_ARG_RANGE;
        return; /* nobody can tell whether it was meant: stay as we are */
    }
    for (uint8_t k = 1; k < HB_PC_ARGS; k++) {
        if (a[k] != HB_UNUSED && (a[k] == 0 || a[k] > HB_MAX_SELECT_ID)) {
            g_state.last_error = HB_ERR_ARG_RANGE;
            return;
        }
    }
    g_state.addressed = 1;
    g_state.selected = 0;
    if (a[0] == 0) {
        g_state.selected = 1;
        g_state.rank = g_state.id ? (uint8_t)(g_state.id - 1u) : 0;
    } else {
        for (uint8_t k = 0; k < HB_PC_ARGS; k++) {
            if (a[k] == g_state.id) {
                g_state.selected = 1;
                g_state.rank = k;
                break;
            }
        }
    }
    if (g_state.selected)
        reply_ack(HB_FN_SELECT);
}

static void comm_function(uint8_t code, const uint8_t *a, tick_t received)
{
    switch (code) {
    case HB_FN_IR_SEL:
        reply_ack(code); /* on the centre, where the PC hears it */
        comm_ir_select(a[0]);
        last_ir_byte = tick_now();
        return;
    case HB_FN_REF:
        g_state.reference = 1;
        g_state.localized = 1;
        g_state.role = HB_ROLE_SUBSTRATE;
        g_state.x = g_state.y = 0;
        g_state.yref = 0;
        for (uint8_t k = 0; k < HB_REF_SHOWS; k++)
            leds_run(HB_FN_LYREF, (const uint8_t *)"\0");
        break;
    case HB_FN_LOCALIZE:
        localize(code, received);
        return;
    case HB_FN_CW:
    case HB_FN_CCW:
        combined_rotation(code, a);
        return;
    case HB_FN_STATUS:
        reply_status();
        return;
    case HB_FN_SET_ROLE:
        g_state.role = a[0];
        break;
    case HB_FN_CLEAR_ERROR:
        g_state.last_error = HB_ERR_NONE;
        break;
    default:
        leds_run(code, a);
        break;
    }
    reply_ack(code);
}

static void handle_frame(const uint8_t *f, tick_t received, uint8_t framing, uint8_t target)
{
    uint8_t code = f[1];
    const uint8_t *a = &f[2];
    reply_begin(framing, target != 0, code);
    if (code == HB_FN_SELECT) {
        select_modules(a);
        return;
    }
    if (!reply_direct() && g_state.addressed && !g_state.selected)
        return;
    uint8_t board = table_board(code);
    if (board == HB_BOARD_NONE)
        reply_ack(HB_UNUSED);
    else if (!table_args_ok(code, a, HB_PC_ARGS))
        reply_err(code, HB_ERR_ARG_RANGE);
    else if (board == HB_BOARD_CONTROL)
        control_function(code, a);
    else
        comm_function(code, a, received);
}

/* --- boot ----------------------------------------------------------------- */

static const uint8_t flash_args[2] = {3, 10};

/* Control board handshake with its LED shows; returns the BOOT_* texts due. */
static uint8_t handshake(void)
{
    uint8_t texts = BOOT_COMM_LISTENING;
    tick_t start = tick_now();
    tick_t probe = (tick_t)(start + HB_HANDSHAKE_PROBE_TICKS);
    while (!control_ready && !g_state.control_up && tick_since(start) < HB_HANDSHAKE_TICKS) {
        uint8_t mark = sys_io_events;
        if ((int16_t)(tick_now() - probe) >= 0) { /* a listening board answers 'L' id */
            uart_putc(CTRL, HB_LINK_READY);
            probe = (tick_t)(tick_now() + HB_HANDSHAKE_RETRY_TICKS);
        }
        poll_inputs();
        if (!control_ready && !g_state.control_up)
            sys_idle_until(ir_due(tick_earlier((tick_t)(start + HB_HANDSHAKE_TICKS), probe)),
                           mark);
    }
    if (control_ready) {
        leds_run(HB_FN_LFLASH1, flash_args);
        texts |= BOOT_CTR_READY;
        start = tick_now();
        tick_t last = start;
        while (!g_state.control_up && tick_since(start) < HB_HANDSHAKE_TICKS) {
            uint8_t mark = sys_io_events;
            if (tick_since(last) >= HB_HANDSHAKE_RETRY_TICKS) {
                uart_putc(CTRL, HB_LINK_READY);
                last = tick_now();
            }
            poll_inputs();
            if (!g_state.control_up)
                sys_idle_until(ir_due(tick_earlier((tick_t)(start + HB_HANDSHAKE_TICKS),
                                                   (tick_t)(last + HB_HANDSHAKE_RETRY_TICKS))),
                               mark);
        }
    }
    if (g_state.control_up) {
        leds_run(HB_FN_LFLASH2, flash_args);
        texts |= BOOT_CTR_LISTENING;
    }
    return texts;
}

/* Boot texts on the IR link. "COMM. BOARD READY" goes out at once on every
 * module (no id yet: the texts are identical). The texts that carry the id
 * wait for this module's boot slot and go out while LColor runs
 * (poll_inputs() feeds the transmitter); return once they are on the air. */
static void __attribute__((noinline)) boot(void)
{
    uint8_t text[REPLY_BYTES_BOOT];
    uart_write(IR, text, reply_boot_text(text, BOOT_COMM_READY));
    uint8_t texts = handshake();
    uint8_t rank = g_state.id ? (uint8_t)((g_state.id - 1u) % HB_BOOT_SLOTS) : 0u;
    tick_t at = HB_BOOT_FIRST_SLOT_TICKS + (tick_t)rank * BOOT_SLOT_TICKS;
    while ((int16_t)(tick_now() - at) < 0) { /* ticks count from reset */
        uint8_t mark = sys_io_events;
        poll_inputs();
        sys_idle_until(ir_due(at), mark);
    }
    boot_left = reply_boot_text(text, texts);
    boot_next = text;
    leds_run(HB_FN_LCOLOR, flash_args);
    tick_t start = tick_now();
    while (boot_left && tick_since(start) < BOOT_SLOT_TICKS) {
        uint8_t mark = sys_io_events;
        poll_inputs();
        if (boot_left)
            sys_idle_until(ir_due((tick_t)(start + BOOT_SLOT_TICKS)), mark);
    }
    boot_left = 0; /* text[] is about to go */
    uart_flush(IR);
}

int main(void)
{
    comm_board_init(); /* LEDs off, selector on the centre */
    sys_init();
    uart_init(CTRL, HB_UBRR_BOARD);
    uart_init(IR, HB_UBRR_IR);
    frame_init(&pc_rx, HB_PC_FRAME_LEN, HB_PC_BYTE_TIMEOUT_TICKS);
    g_state.role = HB_ROLE_MOBILE;
    leds_init(wait_or_abort);
    reply_init(poll_inputs, ir_due);

    /* A restart the PC did not ask for leaves its trace in Status. */
    uint8_t why = sys_reset_flags();
    if (why & (1u << WDRF))
        g_state.last_error = HB_ERR_WATCHDOG_RESET;
    else if (why & (1u << BORF))
        g_state.last_error = HB_ERR_BROWN_OUT;

    boot();
    inbox_clear(); /* nothing sent during boot is for us */
    booted = 1;

    /* Idle: sleep through the ticks until a byte comes or a time-out is due
     * (docs/firmware.md, "The idle path"). */
    for (;;) {
        uint8_t mark = sys_io_events;
        inbox_entry_t next;
        if (poll_inputs() && inbox_take(&next)) {
            handle_frame(next.frame, next.received, next.framing, next.target);
        } else {
            tick_t due = ir_due(tick_now() + SYS_IDLE_MAX_TICKS);
            if (comm_ir_channel() != IR_CENTRE) {
                if (tick_since(last_ir_byte) > HB_IRSEL_HOLD_TICKS)
                    comm_ir_select(IR_CENTRE);
                else
                    due = tick_earlier(due, (tick_t)(last_ir_byte + HB_IRSEL_HOLD_TICKS + 1u));
            }
            sys_idle_until(due, mark);
        }
    }
}
