/* pins.h - accessors for a pin as one byte (HB_PIN of the generated
 * hexbot_pins.h: port index << 3 | bit). Only the board files use it;
 * nothing else in the firmware names a pin. */
#ifndef PINS_H
#define PINS_H

#include <avr/io.h>
#include <avr/pgmspace.h>
#include <stdint.h>

#include "hexbot_pins.h"

static inline volatile uint8_t *pin_port_reg(uint8_t pin)
{
    switch (pin >> 3) {
    case HB_PORT_A: return &PORTA;
    case HB_PORT_B: return &PORTB;
    case HB_PORT_C: return &PORTC;
    case HB_PORT_D: return &PORTD;
    default: return &PORTE;
    }
}

static inline void pin_write(uint8_t pin, uint8_t high)
{
    volatile uint8_t *reg = pin_port_reg(pin);
    uint8_t mask = (uint8_t)(1u << (pin & 7u));
    if (high)
        *reg |= mask;
    else
        *reg &= (uint8_t)~mask;
}

/** Write the pin of entry @p n (1-based: side or joint number) of a pin
 *  table in flash. */
static inline void pin_write_nth_P(const uint8_t *table, uint8_t n, uint8_t high)
{
    pin_write(pgm_read_byte(&table[n - 1u]), high);
}

#endif /* PINS_H */
