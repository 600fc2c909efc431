/* table.c - dispatch facts expanded from the X-macros of hexbot_codes.h,
 * so the firmware never repeats the protocol table. */
#include "table.h"

#include "hexbot_codes.h"

/* gcc would turn these switches into lookup tables in .data, i.e. SRAM
 * (72 bytes each); compare and branch in flash instead. */
#define IN_FLASH __attribute__((optimize("no-tree-switch-conversion")))

IN_FLASH uint8_t table_board(uint8_t code)
{
    switch (code) {
#define X(c, board, nargs) \
    case c:                \
        return board;
        HB_FUNCTIONS(X)
#undef X
    default:
        return HB_BOARD_NONE;
    }
}

uint8_t table_args_ok(uint8_t code, const uint8_t *args, uint8_t slots)
{
#define X(c, n, lo, hi)                                                             \
    if (code == (c) && ((c) != HB_FN_SELECT || (n) == 1) &&                         \
        (uint8_t)(args[(n) - 1] - (uint8_t)(lo)) > (uint8_t)((hi) - (lo)))         \
        return 0;
    HB_ARG_RANGES(X)
#undef X
    /* The filler tells a frame from noise that happens to have its length:
     * the host sends 'N' in every byte the function does not use. */
    for (uint8_t k = table_nargs(code); k < slots; k++)
        if (args[k] != HB_UNUSED)
            return 0;
    return 1;
}

IN_FLASH uint8_t table_nargs(uint8_t code)
{
    switch (code) {
#define X(c, board, nargs) \
    case c:                \
        return nargs;
        HB_FUNCTIONS(X)
#undef X
    default:
        return 0;
    }
}
