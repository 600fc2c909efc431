/* comm_board.c - the communication board's LEDs (Table 3-3) and IR
 * channel selector (Table 3-5), with the pins of the generated
 * hexbot_pins.h (protocol/pins.py): channel Yk is selected by k = 4C + 2B + A.
 */
#include "comm_board.h"

#include <avr/io.h>
#include <avr/pgmspace.h>

#include "pins.h"
#include "uart.h"

/* Side LEDs "(1)" = positive, "(2)" = negative; index = side - 1. */
static const uint8_t led_side_p[6] PROGMEM = HB_LED_SIDE_P_PINS;
static const uint8_t led_side_n[6] PROGMEM = HB_LED_SIDE_N_PINS;
static const uint8_t led_joint[6] PROGMEM = HB_LED_JOINT_PINS;

#ifndef HB_SEL_PORT_A
#error "comm_ir_select() writes the selector lines on PORTA"
#endif
#define SEL_A HB_SEL_A_BIT
#define SEL_B HB_SEL_B_BIT
#define SEL_C HB_SEL_C_BIT
#define SEL_MASK ((1 << SEL_A) | (1 << SEL_B) | (1 << SEL_C))

/* Table 3-5: channel (0 centre, side 1..6) -> multiplexer input Yk. */
static const uint8_t channel_y[7] PROGMEM = HB_IR_CHANNEL_Y;

static uint8_t ir_channel;

void comm_board_init(void)
{
    /* LEDs off = outputs high; selector on the centre; unused pins low. */
    PORTA = HB_LED_MASK_A;
    PORTC = HB_LED_MASK_C;
    PORTD = HB_LED_MASK_D | (1 << PD0); /* pull-up on RX0 */
    PORTE = HB_LED_MASK_E;
    PORTB = (1 << PB2);                 /* pull-up on RX1 */
    DDRA = 0xFF;
    DDRB = (uint8_t)~(1 << PB2);        /* PB2 = RX1 (IR receive) */
    DDRC = 0xFF;
    DDRD = (uint8_t)~(1 << PD0);        /* PD0 = RX0 (control board) */
    DDRE = HB_LED_MASK_E;
    ir_channel = 0xFF;
    comm_ir_select(IR_CENTRE);
}

void comm_led_side(uint8_t side, uint8_t pole, uint8_t on)
{
    const uint8_t *table = pole == POLE_P ? led_side_p : led_side_n;
    pin_write_nth_P(table, side, !on);
}

void comm_led_joint(uint8_t joint, uint8_t on)
{
    pin_write_nth_P(led_joint, joint, !on);
}

void comm_ir_select(uint8_t ch)
{
    if (ch >= sizeof channel_y)
        ch = IR_CENTRE;
    if (ch == ir_channel)
        return;
    /* Bytes still in the shift register would go out on the new channel. */
    uart_flush(UART1);
    uint8_t y = pgm_read_byte(&channel_y[ch]);
    uint8_t bits = (uint8_t)(((y & 1u) ? (1 << SEL_A) : 0) | ((y & 2u) ? (1 << SEL_B) : 0) |
                             ((y & 4u) ? (1 << SEL_C) : 0));
    PORTA = (uint8_t)((PORTA & (uint8_t)~SEL_MASK) | bits);
    ir_channel = ch;
    /* Whatever the receiver collected belongs to the old channel. */
    uart_rx_clear(UART1);
}

uint8_t comm_ir_channel(void)
{
    return ir_channel;
}
