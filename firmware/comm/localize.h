/* localize.h - cluster localization by MSG1 flooding (code 66). */
#ifndef LOCALIZE_H
#define LOCALIZE_H

#include <stdint.h>

#include "system.h"

/* Timing, in 10 ms ticks (300 baud: one byte = 3.33 ticks, MSG1 = 27).
 * A listener stays LISTEN ticks on each side waiting for any byte (one byte
 * time plus the teacher's gap between messages, plus one tick of rounding);
 * when one comes it stays up to CATCH ticks to collect eight consecutive
 * bytes, which hold one whole MSG1 in some rotation. A teacher repeats MSG1
 * on each side for DWELL ticks: a listener may need a full cycle of its six
 * sides to come round, then CATCH ticks. */
#define LOC_LISTEN_TICKS 6u
#define LOC_CATCH_TICKS 40u
#define LOC_DWELL_TICKS (6u * LOC_LISTEN_TICKS + LOC_CATCH_TICKS + 4u)
#define LOC_SWEEP_TICKS (6u * LOC_DWELL_TICKS)
/* The flood runs for a fixed window from the end of the 66 frame (common to
 * every module that heard it), long enough for LOC_HOPS hops from a localized
 * module (the thesis' Fig. 5-8 cluster is 4 hops deep from its base); then
 * every module answers in its slot. A second 66 spreads further: modules
 * keep their localization. */
#define LOC_HOPS 4u
#define LOC_WINDOW_TICKS (LOC_HOPS * (LOC_SWEEP_TICKS + 6u * LOC_LISTEN_TICKS) + 20u)

typedef enum { LOC_KNOWN = 0, LOC_LEARNED, LOC_NOT_HEARD } loc_result_t;

/** Take part in one localization flood (blocks for LOC_WINDOW_TICKS). */
loc_result_t localize_run(tick_t started);

#endif /* LOCALIZE_H */
