/* localize.c - localization of a whole connected cluster from one 66.
 *
 * Every module that hears the 66 frame starts the flood at the same moment.
 * A localized module (the reference, or one localized before) teaches: on
 * each body side b in turn it repeats MSG1 for HB_LOC_DWELL_TICKS, carrying the
 * cell of the neighbour behind global side g = b + yref (Table 4-1) and the
 * global side S = g + 3 through which that neighbour hears it. A module that
 * is not localized listens on its sides in turn; on hearing a valid MSG1 on
 * body side j it takes the position and yref = S - j (mod 6), then teaches
 * in turn. No side sensing is needed: a side without a neighbour has no
 * listener. Only one neighbour can face a given side, so two teachers never
 * reach the same receiver at once.
 */
#include "localize.h"

#include "comm_board.h"
#include "hexbot_codes.h"
#include "leds.h"
#include "state.h"
#include "uart.h"

#define IR UART1
#define MSG_BYTE_TICKS 10u /* 3 byte times between the bytes of one MSG1 */

/* Table 4-1: neighbour offset per global side 1..6. */
static const int8_t dx[6] = HB_SIDE_DX;
static const int8_t dy[6] = HB_SIDE_DY;

static uint8_t wrap6(int8_t v) /* any small integer onto 1..6 */
{
    while (v < 1)
        v += 6;
    while (v > 6)
        v -= 6;
    return (uint8_t)v;
}

static uint8_t deadline_passed(tick_t started)
{
    return tick_since(started) >= HB_LOC_WINDOW_TICKS;
}

static void put_coord(int8_t v)
{
    uint8_t a = (uint8_t)(v < 0 ? -v : v);
    uart_putc(IR, v < 0 ? '-' : '+');
    uart_putc(IR, (uint8_t)('0' + a / 10u));
    uart_putc(IR, (uint8_t)('0' + a % 10u));
}

static uint8_t is_sign(uint8_t c)
{
    return c == '+' || c == '-';
}

static uint8_t is_digit(uint8_t c)
{
    return c >= '0' && c <= '9';
}

static int8_t coord(const uint8_t *p)
{
    int8_t v = (int8_t)((p[1] - '0') * 10 + (p[2] - '0'));
    return p[0] == '-' ? (int8_t)-v : v;
}

static uint8_t valid_msg1(const uint8_t *m)
{
    return m[0] == HB_START && is_sign(m[1]) && is_digit(m[2]) && is_digit(m[3]) &&
           is_sign(m[4]) && is_digit(m[5]) && is_digit(m[6]) && m[7] >= '1' && m[7] <= '6';
}

/* Collect bytes from the selected side, starting with @p b (the byte that
 * showed activity), until the last eight consecutive ones hold a whole
 * MSG1: the teacher repeats it back to back, so any eight consecutive bytes
 * are one message in some rotation. A gap longer than a few byte times
 * breaks the run. */
static uint8_t catch_msg1(uint8_t *m, int16_t b, tick_t started)
{
    uint8_t ring[HB_LOC_FRAME_LEN];
    uint8_t n = 0;
    tick_t t0 = tick_now();
    while (tick_since(t0) < HB_LOC_CATCH_TICKS && !deadline_passed(started)) {
        if (b < 0) {
            n = 0;
        } else {
            ring[n % HB_LOC_FRAME_LEN] = (uint8_t)b;
            n++;
            if (n >= HB_LOC_FRAME_LEN) {
                uint8_t at = n % HB_LOC_FRAME_LEN; /* oldest byte in the ring */
                for (uint8_t k = 0; k < HB_LOC_FRAME_LEN; k++) {
                    if (ring[(uint8_t)(at + k) % HB_LOC_FRAME_LEN] != HB_START)
                        continue;
                    for (uint8_t i = 0; i < HB_LOC_FRAME_LEN; i++)
                        m[i] = ring[(uint8_t)(at + k + i) % HB_LOC_FRAME_LEN];
                    if (valid_msg1(m))
                        return 1;
                }
                if (n >= 2u * HB_LOC_FRAME_LEN)
                    n = HB_LOC_FRAME_LEN; /* keep the index small, same rotation */
            }
        }
        b = uart_getc_wait(IR, MSG_BYTE_TICKS);
    }
    return 0;
}

/* Listen on each body side in turn; returns the side a MSG1 came from, 0 if none. */
static uint8_t listen(tick_t started)
{
    uint8_t m[HB_LOC_FRAME_LEN];
    while (!deadline_passed(started)) {
        for (uint8_t j = 1; j <= 6 && !deadline_passed(started); j++) {
            comm_ir_select(j);
            comm_led_side(j, POLE_N, 1);
            int16_t b = uart_getc_wait(IR, HB_LOC_LISTEN_TICKS);
            uint8_t got = b >= 0 && catch_msg1(m, b, started);
            comm_led_side(j, POLE_N, 0);
            if (got) {
                g_state.x = coord(&m[1]);
                g_state.y = coord(&m[4]);
                g_state.heard_side = (uint8_t)(m[7] - '0');
                g_state.yref = (uint8_t)(wrap6((int8_t)(g_state.heard_side - j + 1)) - 1u);
                g_state.localized = 1;
                return j;
            }
        }
    }
    return 0;
}

/* Send MSG1 on every body side but @p skip (the side we learned from). */
static void teach(tick_t started, uint8_t skip)
{
    for (uint8_t b = 1; b <= 6 && !deadline_passed(started); b++) {
        if (b == skip)
            continue;
        uint8_t side = wrap6((int8_t)(b + g_state.yref));
        int16_t nx = g_state.x + dx[side - 1u];
        int16_t ny = g_state.y + dy[side - 1u];
        if (nx > HB_LOC_COORD_LIMIT || nx < -HB_LOC_COORD_LIMIT || ny > HB_LOC_COORD_LIMIT ||
            ny < -HB_LOC_COORD_LIMIT)
            continue;
        uint8_t facing = wrap6((int8_t)(side + 3u));
        comm_ir_select(b);
        comm_led_side(b, POLE_P, 1);
        comm_led_side(b, POLE_N, 1);
        tick_t t0 = tick_now();
        while (tick_since(t0) < HB_LOC_DWELL_TICKS && !deadline_passed(started)) {
            uart_putc(IR, HB_START);
            put_coord((int8_t)nx);
            put_coord((int8_t)ny);
            uart_putc(IR, (uint8_t)('0' + facing));
            uart_flush(IR); /* at most one MSG1 queued: the dwell stays exact */
        }
        comm_led_side(b, POLE_P, 0);
        comm_led_side(b, POLE_N, 0);
    }
    comm_ir_select(IR_CENTRE);
}

loc_result_t localize_run(tick_t started)
{
    loc_result_t result = LOC_KNOWN;
    uint8_t heard_on = 0;
    leds_all(0);
    if (!g_state.localized) {
        heard_on = listen(started);
        result = heard_on ? LOC_LEARNED : LOC_NOT_HEARD;
    }
    if (g_state.localized)
        teach(started, heard_on);
    comm_ir_select(IR_CENTRE);
    while (!deadline_passed(started))
        sys_idle_until((tick_t)(started + HB_LOC_WINDOW_TICKS), sys_io_events);
    return result;
}
