// *****

// Este programa genera una señal PWM de 32KHz (Timer 1 - OC1A – Fast PWM)
// con una resolución de 0.4% (ICR1 = 247). Este se va a emplear para hacer la
// prueba a lazo abierto y determinar la relación entre la cantidad de pulsos de
// encoder y el desplazamiento lineal de cada eje.

// SALIDAS:
// PB5: Señal PWM
// PB0: Bit de giro

// ENTRADAS:
// PE4: INT4 (interrupción por pulsos de encoder)
// PE5: INT5 (interrupción por detección de sobrecorriente en el motor)

#include <avr/io.h> // Declaración de librerías
#include <avr/interrupt.h>
#include <avr/signal.h>
#include <stdint.h>

#include <avr/delay.h>
#define F_CPU 8000000UL // Frecuencia del oscilador interno: 8 MHz

uint16_t palabra, pulsos=0; // Declaración de variables globales
uint8_t pulso1, pulso2, cont=0, pwm;

// Sub rutina de interrupción por pulsos de encoder

SIGNAL(SIG_INTERRUPT4) {
pulsos++;
}

// Sub rutina de interrupción por sobrecorriente

SIGNAL(SIG_INTERRUPT5) {
TCCR1A=0x00; // Se detiene la generación de la señal PWM
TCCR1B=0x00;
}

// Sub rutina de configuración de puertos de entrada/salida

void config_puertos(void) {
DDRC=255;
PORTC=0b00000000;
DDRB=0b01100001; // PB5=OC1A, PB6=OC1B
PORTB=PORTB | 0b00000000; // bit de giro (PB0)
}

// Sub rutina de configuración del puerto serial

void config_serial(void) {
UBRR0H = 0x00;
UBRR0L = 0x19; // velocidad de transmisión: 38400bps
UCSR0A = 0x02; //inicialización del registro de control
UCSR0C = 0x86; //habitación de transmisión
UCSR0B = 0x18; //comunicación asíncrona, sin paridad, 1 bit de parada, 8 bits de
// datos
}

// Sub rutina de configuración de las interrupciones externas

void config_int4_int5(void) {

EICRB = EICRB | 0b00001111; // INT4 e INT5 configuradas por detección de flanco

    // de subida

EIMSK = EIMSK | 0b00110000; // Habilitación de INT4 e INT5

}

// Sub rutina de configuración del canal PWM

void config_pwm(void) {

TCCR1A=0b10000010; // Sin pre escalamiento, COM1A1 1 y COM1A0 = 0

TCCR1B=0b00011001; // Modo 14: Fast PWM

OCR1A =1;

ICR1=247;

}

// Sub rutina de envío de datos por el puerto serial del microcontrolador hacia el
// Labview

void envio_serial(void) {

    pulso1 = pulsos & 0x00FF; // LSB

    palabra = pulsos >> 8;

    pulso2 = palabra & 0x00FF; // MSB

    if((UCSR0A & 0x20) == 0x20 )
    { UDR0=pulso1; //Primero se envía el LSB
    }

    _delay_loop_2(20000); // Retardo

    if((UCSR0A & 0x20) == 0x20 )
    { UDR0=pulso2; //Por último se envía el MSB
    }

}

// Programa principal
int main(void){

cli(); // Desabilitación de interrupciones

// Se invocan a las sub rutinas de configuración
config_puertos();
config_serial();
config_int4_int5();
config_pwm();

sei();// Habilitación de interrupciones

while(1) {
while(pulsos==0) { //Mientras no se reciba pulsos provenientes del encoder o no
// se desplace el eje, se va aumentando en 0.4% el ciclo de
// de trabajo de la señal PWM

_delay_loop_2(65530); // Retardo de 32ms
_delay_loop_2(65530); // Retardo de 32ms
OCR1A++;
if (OCR1A>=247)
OCR1A=0;
else
;
} //Fin del While pulsos== 0

while(pulsos<1300) { // Condición de parada. Esta sirve para detener el motor
    // y calcular la relación que existe entre el desplazamiento
    // lineal y la cantidad de pulsos enviados por el encoder.

    envio_serial(); // Se invoca a la sub rutina de envío serial de datos al Labview
    _delay_loop_2(65530); // Retardo de 32ms

} // Fin de la condición de parada

TCCR1A=0x00; // Se detiene la generación de la señal PWM en el puerto OC1A
TCCR1B=0x00;

} // Fin del While (1)

} // Fin del Programa principal
