/* localize.h - cluster localization by MSG1 flooding (code 66). */
#ifndef LOCALIZE_H
#define LOCALIZE_H

#include <stdint.h>

#include "hexbot_codes.h"
#include "system.h"

/* Timing (HB_LOC_* of hexbot_codes.h, from protocol/timing.py, which says
 * how each is chosen): a listener stays HB_LOC_LISTEN_TICKS on each side
 * waiting for any byte, then up to HB_LOC_CATCH_TICKS to collect one whole
 * MSG1; a teacher repeats MSG1 on each side for HB_LOC_DWELL_TICKS. The
 * flood runs for HB_LOC_WINDOW_TICKS from the end of the 66 frame (common
 * to every module that heard it); then every module answers in its slot.
 * A second 66 spreads further: modules keep their localization. */

typedef enum { LOC_KNOWN = 0, LOC_LEARNED, LOC_NOT_HEARD } loc_result_t;

/** Take part in one localization flood (blocks for HB_LOC_WINDOW_TICKS). */
loc_result_t localize_run(tick_t started);

#endif /* LOCALIZE_H */
