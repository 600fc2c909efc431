/* id_text.h - a module id as the texts print it (docs/protocol.md, "Module
 * ids"): decimal, at least two digits, so ids 1..99 keep the thesis' bytes
 * ("ID=07", "M07: ") and ids 100..255 take a third digit ("ID=200"). */
#ifndef ID_TEXT_H
#define ID_TEXT_H

#include <stdint.h>

#include "hexbot_codes.h"

#define ID_TEXT_MAX HB_ID_MAX_DIGITS /* digits of the largest id, 255 */

/** Write @p id into @p buf (ID_TEXT_MAX bytes at least, no NUL); returns
 *  the number of digits written, 2 or 3. */
uint8_t id_text(uint8_t *buf, uint8_t id);

#endif /* ID_TEXT_H */
