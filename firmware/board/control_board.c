/* control_board.c - joints, magnets and DIP switches of the control board
 * (Table 3-4), with the pins of the generated hexbot_pins.h (protocol/pins.py). */
#include "control_board.h"

#include <avr/io.h>
#include <avr/pgmspace.h>

#include "pins.h"

static const uint8_t joint_pin[6] PROGMEM = HB_JOINT_PINS;
/* Side i "(1)" line = positive, "(2)" line = negative. */
static const uint8_t magnet_p[6] PROGMEM = HB_MAGNET_P_PINS;
static const uint8_t magnet_n[6] PROGMEM = HB_MAGNET_N_PINS;

#ifndef HB_JOINT_PORT_A
#error "control_joints_all() writes the joints on PORTA"
#endif
#if defined(HB_MAGNET_MASK_A) || defined(HB_MAGNET_MASK_C) || defined(HB_MAGNET_MASK_E)
#error "control_magnets_all_off() clears the magnet lines on PORTB and PORTD only"
#endif

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
        PORTA |= HB_JOINT_MASK_A;
    else
        PORTA &= (uint8_t)~HB_JOINT_MASK_A;
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
    PORTB &= (uint8_t)~HB_MAGNET_MASK_B;
    PORTD &= (uint8_t)~HB_MAGNET_MASK_D;
}

uint8_t control_module_id(void)
{
    return HB_DIP_PIN & HB_DIP_ID_MASK; /* all eight switches: 1..255, 0 = none on */
}
