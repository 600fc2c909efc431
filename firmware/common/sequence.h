/* sequence.h - the control board's functions (codes 1-24) on a set of
 * outputs, and the timed patterns they and the LED functions share.
 *
 * The control board runs them on its joints and magnets; the comm board
 * runs the same ones on the LEDs that show them (joint LED = joint open,
 * side LED of a pole = magnet on with that pole) after the control board's
 * echo. Every wait goes through the hook given to seq_init(); when it
 * reports a new command the pattern stops at once and the board's stop()
 * switches everything off.
 */
#ifndef SEQUENCE_H
#define SEQUENCE_H

#include <stdint.h>

#include "system.h"

/** Wait @p ticks; returns 1 when the running pattern must stop. */
typedef uint8_t (*wait_fn)(tick_t ticks);

/** Output i (1..6; ignored by outputs that stand for a group) on or off. */
typedef void (*set_fn)(uint8_t i, uint8_t on);

/* Magnet poles, as both boards number them. */
#define SEQ_POS 0u
#define SEQ_NEG 1u

/** What the control functions drive. */
typedef struct {
    set_fn joint;                               /* joint i open / closed */
    void (*joints)(uint8_t open);               /* every joint */
    void (*magnet)(uint8_t side, uint8_t pole); /* on; the other line released first */
    void (*magnet_off)(uint8_t side);
    void (*magnets_off)(void);
} seq_outputs_t;

typedef enum { SEQ_MCW, SEQ_MCCW, SEQ_SCW, SEQ_SCCW } seq_rotation_t;

/** @p wait paces every pattern; @p stop switches every output off. */
void seq_init(wait_fn wait, void (*stop)(void));

/** Wait @p ticks through the hook; 1 (after stop()) when the pattern must
 *  stop. SEQ_WAIT returns from the calling pattern then. */
uint8_t seq_wait(tick_t ticks);
#define SEQ_WAIT(t)          \
    do {                     \
        if (seq_wait(t))     \
            return;          \
    } while (0)

/** 1 when a pattern was stopped by the wait hook since the last call. */
uint8_t seq_take_stopped(void);

/** Side/joint i + k around the hexagon, for i in 1..6 and k in -6..6. */
uint8_t seq_around(uint8_t i, int8_t k);

/** @p n rounds; in each, for i = 1..@p last, every output of @p sets in turn
 *  is on for @p t ticks, then off for @p t ticks. */
void seq_walk(uint8_t n, uint8_t t, uint8_t last, const set_fn *sets, uint8_t nsets);

/** Rotation @p r of Table 3-1 about joint a[0] with times t1..t3 = a[1..3]
 *  (ticks); ends with stop(). */
void seq_rotation(const seq_outputs_t *out, seq_rotation_t r, const uint8_t *a);

/** Control function @p code (1-24, arguments range-checked) on @p out. */
void seq_run_function(const seq_outputs_t *out, uint8_t code, const uint8_t *a);

#endif /* SEQUENCE_H */
