/* id_text.c - a module id in decimal, two or three digits. */
#include "id_text.h"

uint8_t id_text(uint8_t *buf, uint8_t id)
{
    uint8_t n = 0;
    if (id >= 100u)
        buf[n++] = (uint8_t)('0' + id / 100u);
    buf[n++] = (uint8_t)('0' + (id / 10u) % 10u);
    buf[n++] = (uint8_t)('0' + id % 10u);
    return n;
}
