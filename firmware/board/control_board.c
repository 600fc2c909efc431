/* control_board.c - pin map of the control board (Table 3-4). */
#include "control_board.h"

#include <avr/io.h>
#include <avr/pgmspace.h>

#include "pins.h"

static const uint8_t joint_pin[6] PROGMEM = {
    PIN(PORT_A, 2), PIN(PORT_A, 3), PIN(PORT_A, 5),
    PIN(PORT_A, 4), PIN(PORT_A, 0), PIN(PORT_A, 1),
};
/* Side i "(1)" line = positive, "(2)" line = negative. */
static const uint8_t magnet_p[6] PROGMEM = {
    PIN(PORT_B, 0), PIN(PORT_D, 3), PIN(PORT_B, 6),
    PIN(PORT_D, 4), PIN(PORT_B, 1), PIN(PORT_B, 7),
};
static const uint8_t magnet_n[6] PROGMEM = {
    PIN(PORT_D, 6), PIN(PORT_D, 5), PIN(PORT_D, 7),
    PIN(PORT_B, 4), PIN(PORT_B, 5), PIN(PORT_D, 2),
};

#define JOINT_MASK 0x3Fu              /* PA0..PA5 */
#define MAGNET_MASK_B 0xF3u           /* PB0, PB1, PB4..PB7 */
#define MAGNET_MASK_D 0xFCu           /* PD2..PD7 */

void control_board_init(void)
{
    PORTA = 0;
    PORTB = (1 << PB2);               /* pull-up on RX1 (debug port) */
    PORTC = 0;                        /* DIP switches: plain inputs */
    PORTD = (1 << PD0);               /* pull-up on RX0 */
    PORTE = 0;
    DDRA = 0xFF;
    DDRB = (uint8_t)~(1 << PB2);
    DDRC = 0x00;
    DDRD = (uint8_t)~(1 << PD0);
    DDRE = 0x07;
}

void control_joint(uint8_t joint, uint8_t open)
{
    pin_write_nth_P(joint_pin, joint, open);
}

void control_joints_all(uint8_t open)
{
    if (open)
        PORTA |= JOINT_MASK;
    else
        PORTA &= (uint8_t)~JOINT_MASK;
}

void control_magnet_on(uint8_t side, uint8_t pole)
{
    uint8_t p = pgm_read_byte(&magnet_p[side - 1u]);
    uint8_t n = pgm_read_byte(&magnet_n[side - 1u]);
    /* Release the other line first: both high would short the driver. */
    pin_write(pole ? p : n, 0);
    pin_write(pole ? n : p, 1);
}

void control_magnet_off(uint8_t side)
{
    pin_write_nth_P(magnet_p, side, 0);
    pin_write_nth_P(magnet_n, side, 0);
}

void control_magnets_all_off(void)
{
    PORTB &= (uint8_t)~MAGNET_MASK_B;
    PORTD &= (uint8_t)~MAGNET_MASK_D;
}

uint8_t control_module_id(void)
{
    uint8_t dip = PINC;
    if (dip & 0xC0u)
        return 0;
    return dip & 0x3Fu;
}
