/* rf12_board.c - pins of the wireless board (Appendix A, "Wireless SPI").
 *
 * PB4 nSEL, PB5 SDI (to the radio), PB6 SDO (from the radio), PB7 SCK,
 * PD4 nFFS (held high: FIFO access through commands), PD5 nIRQ, PD6 green
 * LED, PD7 red LED (both active high). The listing also enabled the
 * hardware SPI on the same pins, which overrides PB5/PB7 in master mode;
 * we bit-bang only, as its driver intended.
 */
#include "rf12_board.h"

#include <avr/io.h>

#include "pins.h"

#if !defined(HB_RF12_SPI_PORT_B) || !defined(HB_RF12_CTRL_PORT_D) || !defined(HB_RF12_MODE_PORT_A)
#error "the driver bit-bangs SPI on PORTB, nFFS/nIRQ/LEDs on PORTD, the jumper on PORTA"
#endif
#define SEL HB_RF12_SEL_BIT
#define SDI HB_RF12_SDI_BIT
#define SDO HB_RF12_SDO_BIT
#define SCK HB_RF12_SCK_BIT
#define NFFS HB_RF12_NFFS_BIT
#define NIRQ HB_RF12_NIRQ_BIT
#define LED_G HB_RF12_LED_G_BIT
#define LED_R HB_RF12_LED_R_BIT
#define MODE_JUMPER HB_RF12_MODE_BIT

void rf12_board_init(void)
{
    PORTA = (1 << MODE_JUMPER);                 /* pull-up on the jumper */
    DDRA = 0;
    PORTB = (1 << SEL) | (1 << SDI);            /* deselected, SCK low */
    DDRB = (1 << SEL) | (1 << SDI) | (1 << SCK);
    PORTD = (1 << NFFS) | (1 << NIRQ) | (1 << PD0) | (1 << PD2);
    DDRD = (1 << NFFS) | (1 << LED_G) | (1 << LED_R);
    DDRC = 0;
    DDRE = 0;
}

uint16_t rf12_board_xfer(uint16_t word)
{
    uint16_t in = 0;
    PORTB &= (uint8_t)~(1 << SCK);
    PORTB &= (uint8_t)~(1 << SEL);
    for (uint8_t i = 0; i < 16; i++) {
        if (word & 0x8000u)
            PORTB |= (1 << SDI);
        else
            PORTB &= (uint8_t)~(1 << SDI);
        PORTB |= (1 << SCK);
        word <<= 1;
        in <<= 1;
        if (PINB & (1 << SDO))
            in |= 1u;
        PORTB &= (uint8_t)~(1 << SCK);
    }
    PORTB |= (1 << SEL);
    return in;
}

uint8_t rf12_board_irq(void)
{
    return !(PIND & (1 << NIRQ));
}

void rf12_board_led(uint8_t led, uint8_t on)
{
    uint8_t mask = (uint8_t)(1 << (led == RF12_LED_RED ? LED_R : LED_G));
    if (on)
        PORTD |= mask;
    else
        PORTD &= (uint8_t)~mask;
}

uint8_t rf12_board_tx_mode(void)
{
    return (PINA & (1 << MODE_JUMPER)) != 0;
}
