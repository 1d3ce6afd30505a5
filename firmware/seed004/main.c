#include <avr/io.h>
#include <avr/interrupt.h>
#include <avr/signal.h>
#include <stdint.h>

#define F_CPU 8000000UL

#include <avr/delay.h>
#include <math.h>
#include <stdlib.h>

#define pi 3.14159

//*****
// DECLARACION DE ARREGLOS
//*****

float arr_sp1[480]; // ARREGLO DECLARADO PARA QUE ALMACENE LOS SET
// POINTS DE UN EJE

float arr_sp2[480]; // ARREGLO DECLARADO PARA QUE ALMACENE LOS SET
// POINTS DEL EJE RESTANTE

//*****

uint8_t dato,temp=0; // VARIABLES UTILIZADAS PARA LA RECEPCION

uint16_t dato1,dato2,dato3,dato4; // SERIAL DE LOS SET POINTS

uint8_t min=0,max=50; // LIMITES DEL ANCHO DE PULSO EXPRESADO EN
// PORCENTAJE

uint16_t palabra,indice; // VARIABLES UTILIZADAS PARA LA COMUNICACION
// SERIAL

uint16_t pulsos_x=0,pulsos_y=0; // VARIABLES QUE ALMACENAN LOS PULSOS
// DE ENCODER RECIBIDOS

uint16_t contador=0,cont=0;

uint16_t long1,long2,long3; // VARIABLES QUE ALMACENAN LA CANTIDAD DE
// MUESTRAS POR CADA TRAMO

//*****
// PARAMETROS DEL PEFIL DE VELOCIDAD
//*****

float  spx_ini=0,spy_ini=0; // SE DEFINE AL ORIGEN (0,0) COMO LA
                          //          COORDENADA          INICIAL
float  spx_fin,spy_fin; // VARIABLES QUE ALMACENAN LOS SET POINTS
                          //          RECIBIDOS DESDE LABVIEW

float  sp1_ini,sp1_fin;
float  sp2_ini,sp2_fin;

float  tf,tc,tfx,tfy,pendiente,N,N_total;
float  vel_max=150;
float  acel=300;

//*****

//*****
// PARAMETROS DEL ALGORITMO PID
//*****

float  posx_rad=0,posy_rad=0;// VARIABLES QUE GUARDAN LA POSICION
                          //          ACTUAL DE CADA MOTOR (radianes)

float  error_act_x,error_act_y,error_ant_x,error_ant_y;//  VARIABLES  QUE
                          //          ALMACENAN LOS ERRORES DEL EJE X e Y PARA
                          //          EL ALGORITMO PID

float  salida_x,salida_y; // SALIDA DEL ALGORITMO PID QUE REPRESENTA EL
                          //          VALOR DE DUTY CYCLE EN %

//*****

//*****
// INTERRUPCIONES EXTERNAS
//*****

//*****
// INT4: ENCODER EJE X (PE4)
//*****

    SIGNAL(SIG_INTERRUPT4)

{
    if (spx_fin>spx_ini) // SI EL PUNTO DE LLEGADA DEL EJE "X" ES MAYOR
                        // AL PUNTO DE PARTIDA,

        pulsos_x++;    // SE INCREMENTA EN UNA UNIDAD LA CANTIDAD DE
                        // PULSOS

    else                // LUEGO DE CADA FLANCO DE SUBIDA RECIBIDO
                        // DEL ENCODER

        pulsos_x--;    // EN CASO CONTRARIO, SE DECREMENTA EN UNO.
}

//*****
// INT5: SOBRECORRIENTE X (PE5)
//*****

SIGNAL(SIG_INTERRUPT5)
{
    TCCR1A= 0x00; // SI SE DETECTA SOBRECORRIENTE EN EL MOTOR DEL
    TCCR1B= 0x00; // EJE X, SE DESACTIVA EL CANAL PWM
}

//*****
// INT6: ENCODER EJE Y (PE6)
//*****

SIGNAL(SIG_INTERRUPT6)
{
    if (spy_fin>spy_ini) // SI EL PUNTO DE LLEGADA DEL EJE "Y" ES MAYOR
                        // AL PUNTO DE PARTIDA,

        pulsos_y++;    // SE INCREMENTA EN UNA UNIDAD LA CANTIDAD DE
                        // PULSOS

    else                // LUEGO DE CADA CADA FLANCO DE SUBIDA
                        // RECIBIDO DEL ENCODER

        pulsos_y--;    // EN CASO CONTRARIO, SE DECREMENTA EN UNO.
}

//*****
// INT7: SOBRECORRIENTE Y (PE7)
//*****

SIGNAL(SIG_INTERRUPT7)

{

    TCCR1A= 0x00; // SI SE DETECTA SOBRECORRIENTE EN EL MOTOR DEL
    TCCR1B= 0x00; // EJE Y SE DESACTIVA EL CANAL PWM

}

void config_puertos(void)
{

    DDRB=255; // PB5: PWM X
             // PB6: PWM Y

    PORTB=PORTB | 0b00000000;

    DDRC=255; // PC0: BIT DE GIRO EJE
             // PC1: BIT DE GIRO EJE Y

    PORTC=0;
}

void config_serial(void)
{

    UBRR0H = 0x00;

    UBRR0L = 0x67; // @8Mhz: 0x67 --> 9600bps

    UCSR0A = 0x02; // DOBLE VELOCIDAD: U2X = 1

    UCSR0C = 0x86; // 8 BIT DE DATOS

    UCSR0B = 0x18; // SIN PARIDAD, 1 BIT DE STOP, ASINCRONO

}

void config_pwm(void)
{
    TCCR1A= 0b10100010; // MODO 14: FAST PWM, COM1A1:COM1A0 = 1:0 =
                        // COM1B1:COM1B0

    TCCR1B= 0b00011001; // SIN PREESCALAMIENTO

    OCR1A=1;
    OCR1B=1;
    ICR1=247;
}

void config_int_ext(void)
{
    EICRB = EICRB | 0xFF; // SE CONFIGURA LAS 4 INTERRUPTIONES
                        // EXTERNAS POR FLANCO DE SUBIDA

    EIMSK = EIMSK | 0xF0; // SE HABILITAN LAS ULTIMAS 4 INTERRUPTIONES
                        // EXTERNAS
}

void bits_de_giro(float spx_fin,float spx_ini,float spy_fin,float spy_ini)
{
    // BIT DE GIRO X
    if (spx_fin>spx_ini) // SI LA POSICION FINAL DEL EJE "X" ES MAYOR A LA
                        // POSICION ACTUAL

        PORTC=PORTC | 0b00000000; // EL EJE DEBE AVANZAR, EN CASO
                        // CONTRARIO DEBERÁ RETROCEDER.

    else // AVANCE: BIT = 0 y RETROCESO: BIT = 1

        PORTC=PORTC | 0b00000001;

    // BIT DE GIRO Y
    if (spy_fin>spy_ini) // LO MISMO SE CUMPLE PARA EL EJE "Y"

PORTC=PORTC | 0b00000000;

else

PORTC=PORTC | 0b00000010;

}

// PROGRAMA PRINCIPAL

int main(void) // INICIO DEL PROGRAMA PRINCIPAL
{
float i,j,k;

cli(); // DESABILITACION DE INTERRUPCIONES PARA INVOCAR A
// SUBROUTINAS DE CONFIGURACIÓN

config_puertos();
config_pwm();
config_int_ext();
config_serial();

sei(); // HABILITACIÓN DE INTERRUPCIONES EN EL PROGRAMA

while(1)
{
//*****
// RECEPCION DE LOS SET POINTS
//*****

while(temp<4)
{
if ((UCSR0A & 0x80) == 0x80 )

{
    dato=UDR0;// SE LE ASIGNA UNA VARIABLE ENTERA AL DATO
                // RECIBIDO PARA OBTENER SU CODIGO ASCII

        temp++;

        _delay_loop_2(65530); // @8Mhz: Delay = (1/8000000)*65530*(4)
                                // = 32.8ms

    switch (temp)
    {
        case 1:dato1=dato*256; // PRIMERO RECEPCIONA EL MSB DEL EJE X
            break;
        case 2:dato2=dato; // LUEGO EL LSB DEL EJE X
            break;
        case 3:dato3=dato*256; // DESPUES RECEPCIONA EL MSB DEL EJE Y
            break;
        case 4:dato4=dato; // FINALMENTE EL LSB DEL EJE Y
            break;
    } // FIN DEL SWITCH
} // FIN DEL IF
} // FIN DEL WHILE (TEMP<4)

//*****

spx_fin=dato1+dato2; // SE FORMA EL SET POINT DEL EJE X CON EL LSB Y
                    // MSB RESPECTIVO

spy_fin=dato3+dato4; // SE FORMA EL SET POINT DEL EJE Y CON EL LSB Y
                    // MSB RESPECTIVO

temp=0; // SE REINICIA EL CONTADOR PARA PODER RECIBIR UN SET POINT

//*****
// PERFIL DE VELOCIDAD TRAPEZOIDAL
//*****

//*****
// CALCULO DEL TIEMPO FINAL, TIEMPO CRITICO Y NRO. TOTAL DE
// MUESTRAS
//*****

// TIEMPO FINAL:

// SE CALCULA EL TIEMPO QUE TARDA CADA EJE EN LLEGAR A SU PUNTO
// FINAL. ENTONCES, SE SABE CUAL EJE TARDA MAYOR TIEMPO EN LLEGAR
// A SU PUNTO FINAL

    tfx=((vel_max*vel_max)-acel*(spx_ini-spx_fin))/(acel*vel_max);
    tfy=((vel_max*vel_max)-acel*(spy_ini-spy_fin))/(acel*vel_max);

// CALCULO DE LA PENDIENTE

pendiente=(spy_fin-spy_ini)/(spx_fin-spx_ini);// SE CALCULA LA PENDIENTE

if (tfx>=tfy)
{
    sp1_ini=spx_ini; // SI EL EJE "X" DEMORA MAYOR TIEMPO QUE EL EJE "Y"
    sp1_fin=spx_fin; // EN LLEGAR AL FINAL DE SU RECORRIDO, SE
    sp2_ini=spy_ini; // CONSIDERAN LOS PARÁMETROS DEL EJE "X" PARA
    // CALCULAR EL TIEMPO CRITICO
    sp2_fin=spy_fin; // ESTO PARÁMETROS SON: PUNTO INICIAL, PUNTO
    // FINAL Y TIEMPO FINAL.

    tf=tfx;
}

else
{
    sp1_ini=spy_ini; // EN CASO CONTRARIO, SE CONSIDERAN LOS
    sp1_fin=spy_fin; // PARAMETROS DEL EJE "Y" PARA CALCULAR EL
    sp2_ini=spx_ini; // TIEMPO CRITICO
    sp2_fin=spx_fin;
    tf=tfy;
}

// TIEMPO CRITICO (CALCULADO CON EL EJE DE MAYOR TIEMPO FINAL)
tc= (sp1_ini-sp1_fin+vel_max*tf)/(vel_max);

// NUMERO TOTAL DE MUESTRAS
N_total = tf/0.005; // SE CALCULA LA CANTIDAD TOTAL DE MUESTRAS DEL
// RECORRIDO
N=(N_total/3.00); // SE CALCULA LA CANTIDAD DE MUESTRAS POR CADA
//UNO DE LOS TRES TRAMOS DEL PERFIL DE VELOCIDAD
long1=N_total; // SE ASIGNA A UNA NUEVA VARIABLE PARA UNIFORMIZAR
// LA NOMENCLATURA
long2=N; // SE ASIGNA A UNA NUEVA VARIABLE PARA UNIFORMIZAR LA
// NOMENCLATURA
long3=3*long2; // SE ASIGNA A UNA NUEVA VARIABLE PARA UNIFORMIZAR
// LA NOMENCLATURA

//*****

// SE VERIFICA QUE SE CUMPLA LA CONDICION DE ACELERACION MINIMA
if (tc<(tf/2))
{
    // TRAMO DE ACELERACION
    contador=0;

for (i=0;i<tc;i=i+(tc/(N-1)))
{
arr_sp1[contador]=sp1_ini + 0.5*acel*i*i;
contador++;
}

// TRAMO DE VELOCIDAD CONSTANTE
for (j=tc;j<tf-tc;j=j+((tf-2*tc)/(N-1)))
{
arr_sp1[contador]=sp1_ini+ acel*tc*(j-(tc/2));
contador++;
}

// TRAMO DE DESACELERACION
for (k=(tf-tc);k<tf;k=k+(tc/(N-1)))
{
if(contador>=long3)
{ break;
}
arr_sp1[contador]=sp1_fin - (0.5*acel*(tf-k)*(tf-k));
contador++;
}

contador=0;

// CONOCIENDO EL VALOR DE LA PENDIENTE SE CALCULAN LAS
// POSICIONES DEL EJE DE MENOR TIEMPO FINAL (arr_sp2)

for(contador=0;contador<long3;contador++)
{
arr_sp2[contador]=sp2_ini+ pendiente*(arr_sp1[contador]-sp1_ini);
}

//*****
// CONVERSION DE mm A rad
//*****

// HASTA ESTA ETAPA, SE HAN CALCULADO LOS DOS ARREGLOS QUE
// CONTIENEN LOS SET POINTS DEL RECORRIDO DE CADA EJE PERO
//ESTOS SE ENCUENTRAN EN milímetros. PARA EJECUTAR EL
//CORRECTAMENTE ALGORITMO PID, LOS SET POINTS DEBEN
// ENCONTRARSE EN radianes.

if (tfx>=tfy)

{
  // SI EL TF DEL EJE "X" ES MAYOR QUE EL TF DEL EJE "Y", EL
  // "arr_sp1" CONTIENE LOS SET POINTS DEL EJE "X"

  contador=0; // POR ENDE SE LE APLICA EL FACTOR DE CONVERSIÓN
  // (2.12) DEL EJE "X" A CADA UNO DE LOS ELEMENTOS
  // DEL ARREGLO.

  for(contador=0;contador<long3;contador++)
  {
    arr_sp1[contador]=(arr_sp1[contador]*2*pi)/(2.12);
  }

  contador=0; // EN ESE CASO, EL "arr_sp2" CONTIENE LOS SET POINTS
  // DEL EJE "Y". ENTONCES, SE LE APLICA EL FACTOR DE
  // CONVERSIÓN (2.00) DEL EJE "Y" A CADA UNO DE LOS
  // ELEMENTOS DEL ARREGLO.

  for(contador=0;contador<long3;contador++)
  {
    arr_sp2[contador]=(arr_sp2[contador]*2*pi)/(2.00);
  }

}

else

{ // SI EL TF DEL EJE "Y" ES MAYOR QUE EL TF DEL EJE "X", EL
  // "arr_sp1" CONTIENE LOS SET POINTS DEL EJE "Y"

contador=0;// POR ENDE SE LE APLICA EL FACTOR DE CONVERSIÓN
  // (2.00) DEL EJE "Y" A CADA UNO DE LOS ELEMENTOS
  // DEL ARREGLO.

for(contador=0;contador<long3;contador++)

{

arr_sp1[contador]=(arr_sp1[contador]*2*pi)/(2.00);

}

contador=0; // EN ESE CASO, EL "arr_sp2" CONTIENE LOS SET POINTS
  // DEL EJE "X". ENTONCES, SE LE APLICA EL FACTOR DE

for(contador=0;contador<long3;contador++)

{ // CONVERSIÓN (2.12) DEL EJE "X" A CADA UNO DE LOS ELEMENTOS
  // DEL ARREGLO

arr_sp2[contador]=(arr_sp2[contador]*2*pi)/(2.12);

}

} // FIN DE LA CONVERSION DE mm A rad
} // FIN DE LA CONDICION DE ACELERACION MINIMA

//*****

// SE INVOCA A LA SUBROUTINA RESPECTIVA PARA DETERMINAR LOS
// BITS DE GIRO DEL EJE "X" e "Y"

bits_de_giro(spx_fin,spx_ini,spy_fin,spy_ini);

error_ant_x=0;

error_ant_y=0;

//*****
//ALGORITMO PID
//*****

//EXISTEN DOS POSIBILIDADES DE EJECUCIÓN:

// **1)** SI EL TF DEL EJE "X" ES MAYOR AL TF DEL EJE "Y", EL ARREGLO "arr
 // sp1" CONTIENE LOS SET POINTS DEL EJE "X" Y POR LO TANTO SE LE
 // APLICA LA ECUACION DE DIFERENCIAS DEL EJE RESPECTIVO.
 // MIENTRAS QUE EL ARREGLO "arr_sp2" CONTIENE LOS SET POINTS DEL
 // EJE "Y", AL CUAL SE LE APLICA LA ECUACION DE DIFERENCIAS
 // CORRESPONDIENTE A ESE EJE.

// **2)** SI EL TF DEL EJE "Y" ES MAYOR AL TF DEL EJE "X", EL ARREGLO "arr
 // sp2" CONTIENE LOS SET POINTS DEL EJE "X" Y POR LO TANTO SE LE
 // APLICA LA ECUACION DE DIFERENCIAS DEL EJE RESPECTIVO.
 // MIENTRAS QUE EL ARREGLO "arr_sp1" CONTIENE LOS SET POINTS DEL
 // EJE "Y", AL CUAL SE LE APLICA LA ECUACION DE DIFERENCIAS
 // CORRESPONDIENTE A ESE EJE.

if (tfx>=tfy)
{ // PRIMERA POSIBILIDAD DE EJECUCION

//*****
// EJE X
//*****

contador=0;

for(contador=0;contador<long3;contador++)
{

posx_rad=0.314*pulsos_x;// CONVERSION DE PULSOS DE ENCODER
// DEL EJE "X" A RADIANES

error_act_x=arr_sp1[contador] - posx_rad;// CALCULO DEL ERROR
// ACTUAL DEL EJE "X"

error_act_x=fabs(error_act_x);// VALOR ABSOLUTO DEL ERROR
// ACTUAL DEL EJE "X"

salida_x=(0.198*error_act_x) - (0.179982*error_ant_x); // SE APLICA LA
// ECUACION DE DIFERENCIAS DEL EJE "X"

salida_x=(salida_x)*100;// SE HACE LA CONVERSION A
// PORCENTAJE DE ANCHO DE PULSO

if(salida_x<min) // SE LIMITA LA SEÑAL PWM OBTENIDA
// COMO SALIDA DEL ALGORITMO PID
// PARA NO SATURAR EL MOTOR DEL EJE X

salida_x=min;

if(salida_x>max)

salida_x=max;

// HACEMOS LA SIGUIENTE RELACION: COMO 247 (OCR1A)
// EQUIVALE AL 100% DE PWM, ENTONCES 100/247=0.405. POR LO
// TANTO, CUALQUIER VALOR DE PWM RESULTANTE DEL AL
// ALGORITMO DIVIDIRLO ENTRE 0.405 NOS VA A DAR COMO
// RESULTADO, LUEGO DE REDONDEARLO, UN ENTERO QUE
// CORRESPONDE A SU VALOR DE OCR1A (16 bits)

OCR1A=floor(salida_x/0.405); // REDONDEA AL ENTERO MENOR MAS
//CERCANO

error_ant_x=error_act_x; // EL ERROR ACTUAL SE CONVIERTE EN
// EL ERROR ANTERIOR PARA LA
// SIGUIENTE EJECUCION DEL ALGORITMO PID

_delay_loop_2(10000); // @ 8 Mhz ----->0.125us*10000*(4)
// = 5 ms (Tiempo de muestreo)

} // FIN DEL LAZO FOR DEL EJE X

//*****

// EJE Y

//*****

contador=0;

for(contador=0;contador<long3;contador++)
{
    posy_rad=0.314*pulsos_y; // CONVERSION DE PULSOS DE
                            // ENCODER DEL EJE "Y" A RADIANES
    error_act_y=arr_sp2[contador] - posy_rad; // CALCULO DEL ERROR
                                             // ACTUAL DEL EJE "Y"
    error_act_y=fabs(error_act_y); // VALOR ABSOLUTO DEL ERROR
                                   // ACTUAL DEL EJE "Y"
    salida_y=(0.042*error_act_y) - (0.035994*error_ant_y); // SE APLICA
                                                            // LA ECUACION DE DIFERENCIAS
                                                            // DEL EJE "Y"
    salida_y=(salida_y)*100; // SE HACE LA CONVERSION A
                              // PORCENTAJE DE ANCHO DE PULSO

    if(salida_y<min) // SE LIMITA LA SEÑAL PWM OBTENIDA
                    // COMO SALIDA DEL ALGORITMO PID
                    // PARA NO SATURAR EL MOTOR DEL EJE Y

        salida_y=min;
    if(salida_y>max)
        salida_y=max;

    OCR1B=floor(salida_y/0.405);

    error_ant_y=error_act_y; // EL ERROR ACTUAL SE CONVIERTE EN
                             // EL ERROR ANTERIOR PARA LA
                             // SIGUIENTE EJECUCION DEL ALGORITMO PID

    _delay_loop_2(10000); // @ 8 Mhz -->(1/8Mhz)*10000*(4)= 5 ms (Tiempo
                          // de muestreo)

} // FIN DEL LAZO FOR DEL EJE Y
} // FIN DE LA PRIMERA POSIBILIDAD DE EJECUCION

else

{ // SEGUNDA POSIBILIDAD DE EJECUCION

//*****

// EJE X

//*****

contador=0;

for(contador=0;contador<long3;contador++)

{

posx_rad=0.314*pulsos_x; // CONVERSION DE PULSOS DE ENCODER
//DEL EJE "X" A RADIANES

error_act_x=arr_sp2[contador] - posx_rad; // CALCULO DEL ERROR
// ACTUAL DEL EJE "X"

error_act_y=fabs(error_act_y); // VALOR ABSOLUTO DEL ERROR
// ACTUAL DEL EJE "X"

salida_x=(0.198*error_act_x) - (0.179982*error_ant_x); // SE APLICA LA
// ECUACION DE DIFERENCIAS DEL
// EJE "X"

salida_x=(salida_x)*100; // SE HACE LA CONVERSION A
// PORCENTAJE DE ANCHO DE PULSO

if(salida_x<min) // SE LIMITA LA SEÑAL PWM OBTENIDA COMO
// SALIDA DEL ALGORITMO PID PARA NO
// SATURAR EL MOTOR DEL EJE X

salida_x=min;

if(salida_x>max)

salida_x=max;

OCR1A=floor(salida_x/0.405);

error_ant_x=error_act_x; // EL ERROR ACTUAL SE CONVIERTE EN
                        // EL ERROR ANTERIOR PARA LA
                        // SIGUIENTE EJECUCION DEL ALGORITMO PID

_delay_loop_2(10000);// @ 8 Mhz -->(1/8Mhz)*10000*(4)= 5 ms
                        // (Tiempo de muestreo)

} // FIN DEL LAZO FOR DEL EJE X

//*****
// EJE Y
//*****

contador=0;
for(contador=0;contador<long3;contador++)
{
    posy_rad=0.314*pulsos_y; // CONVERSION DE PULSOS DE
                            // ENCODER DEL EJE "Y" A RADIANTES
    error_act_y=arr_sp1[contador] - posy_rad; // CALCULO DEL ERROR
                                              // ACTUAL DEL EJE "Y"
    error_act_x=fabs(error_act_x); // VALOR ABSOLUTO DEL ERROR
                                  // ACTUAL DEL EJE "Y"
    salida_y=(0.042*error_act_y) - (0.035994*error_ant_y); // SE APLICA LA
                                                            // ECUACION DE DIFERENCIAS DEL EJE "Y"
    salida_y=(salida_y)*100; // SE HACE LA CONVERSION A
                             // PORCENTAJE DE ANCHO DE PULSO

    if(salida_y<min) // SE LIMITA LA SEÑAL PWM OBTENIDA COMO
                    // SALIDA DEL ALGORITMO PID PARA NO SATURAR
                    // EL MOTOR DEL EJE X

        salida_y=min;

    if(salida_y>max)

        salida_y=max;

OCR1B=floor(salida_y/0.405);

error_ant_y=error_act_y; // EL ERROR ACTUAL SE CONVIERTE EN
                          // EL ERROR ANTERIOR PARA LA
                          // SIGUIENTE EJECUCION DEL ALGORITMO PID

_delay_loop_2(10000); // @ 8 Mhz -->(1/8Mhz)*10000*(4)= 5 ms
                      // (Tiempo de muestreo)

} // FIN DEL LAZO FOR DEL EJE Y

} // FIN DE LA SEGUNDA POSIBILIDAD DE EJECUCION

contador=0;

// EL SET POINT ACTUAL SE GUARDA COMO EL SET POINT ANTERIOR
// PARA EL SIGUIENTE MOVIMIENTO

spx_ini=spx_fin;
spy_ini=spy_fin;

} // FIN DEL WHILE (1)

} // FIN DEL PROGRAMA PRINCIPAL
