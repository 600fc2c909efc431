/* hw.h -- register-name differences between the ATmega162 (our core) and
 * simavr's stock atmega128/atmega644 cores, so one test program builds for
 * all three.  Only what the test programs use. */
#ifndef HW_H
#define HW_H
#include <avr/io.h>

#if defined(__AVR_ATmega162__)
#define HW_URSEL(v) ((v) | (1 << URSEL0)) /* UCSRnC write selector */
#define HW_UCSR0C_WRITE(v) (UCSR0C = HW_URSEL(v))
#define HW_UCSR1C_WRITE(v) (UCSR1C = (v) | (1 << URSEL1))
#define HW_UBRR0H_WRITE(v) (UBRR0H = (v) & 0x0F)
#define HW_UBRR1H_WRITE(v) (UBRR1H = (v) & 0x0F)
#define HW_RX0_vect USART0_RXC_vect
#define HW_UDRE0_vect USART0_UDRE_vect
#define HW_TX1_vect USART1_TXC_vect
#define HW_INT0_PIN PD2
#define HW_INT0_FALLING() (MCUCR = (MCUCR & ~3) | (1 << ISC01))
#define HW_INT0_ENABLE() (GICR |= (1 << INT0))
#define HW_MCUSR MCUCSR
#elif defined(__AVR_ATmega128__)
#define HW_UCSR0C_WRITE(v) (UCSR0C = (v))
#define HW_UCSR1C_WRITE(v) (UCSR1C = (v))
#define HW_UBRR0H_WRITE(v) (UBRR0H = (v))
#define HW_UBRR1H_WRITE(v) (UBRR1H = (v))
#define HW_RX0_vect USART0_RX_vect
#define HW_UDRE0_vect USART0_UDRE_vect
#define HW_TX1_vect USART1_TX_vect
#define HW_INT0_PIN PD0
#define HW_INT0_FALLING() (EICRA = (EICRA & ~3) | (1 << ISC01))
#define HW_INT0_ENABLE() (EIMSK |= (1 << INT0))
#define HW_MCUSR MCUCSR
#elif defined(__AVR_ATmega644__)
#define HW_UCSR0C_WRITE(v) (UCSR0C = (v))
#define HW_UBRR0H_WRITE(v) (UBRR0H = (v))
#define HW_RX0_vect USART0_RX_vect
#define HW_UDRE0_vect USART0_UDRE_vect
#endif
#endif
