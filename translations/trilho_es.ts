<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>Controller</name>
    <message>
        <source>%1: Positioning to x=%2 at maximum speed.</source>
        <translation>%1: Posicionamiento a x=%2 con velocidad máxima.</translation>
    </message>
    <message>
        <source>%1: Positioning to x=%2 at %3% of maximum speed.</source>
        <translation>%1: Posicionamiento a x=%2 con %3% de la velocidad máxima.</translation>
    </message>
    <message>
        <source>%1: Waiting %2 s.</source>
        <translation>%1: Esperando %2 s.</translation>
    </message>
    <message>
        <source>%1: Change to absolute coordinates.</source>
        <translation>%1: Cambio a coordenadas absolutas.</translation>
    </message>
    <message>
        <source>%1: Change to incremental coordinates.</source>
        <translation>%1: Cambio a coordenadas incrementales.</translation>
    </message>
    <message>
        <source>%1: System zero changed to x=%2.</source>
        <translation>%1: Cero del sistema cambiado a x=%2.</translation>
    </message>
    <message>
        <source>%1: Return to the rail&apos;s absolute zero.</source>
        <translation>%1: Retorno al cero absoluto del riel.</translation>
    </message>
    <message>
        <source>%1: Feed set to %3% of maximum speed.</source>
        <translation>%1: Avance cambiado a %3% de la velocidad máxima.</translation>
    </message>
    <message>
        <source>%1: Waiting for the Continue key.</source>
        <translation>%1: Esperando la tecla Continuar.</translation>
    </message>
    <message>
        <source>%1: Program jumped to line %2.</source>
        <translation>%1: Programa desviado a la línea %2.</translation>
    </message>
    <message>
        <source>Program finished !</source>
        <translation>¡Programa finalizado!</translation>
    </message>
    <message>
        <source>There are %2 compile error(s)! Nothing moved.</source>
        <translation>¡Hay %2 error(es) de compilación! Nada se movió.</translation>
    </message>
    <message>
        <source>Manual mode.</source>
        <translation>Modo manual.</translation>
    </message>
    <message>
        <source>Automatic mode.</source>
        <translation>Modo automático.</translation>
    </message>
    <message>
        <source>Homing: going to the rail centre.</source>
        <translation>Referenciando: plataforma yendo al centro del riel.</translation>
    </message>
    <message>
        <source>Homing done: platform at the rail centre.</source>
        <translation>Plataforma en el centro del riel.</translation>
    </message>
    <message>
        <source>Careful: left end of travel reached !!!</source>
        <translation>¡¡¡Cuidado: fin de carrera izquierdo alcanzado!!!</translation>
    </message>
    <message>
        <source>Careful: right end of travel reached !!!</source>
        <translation>¡¡¡Cuidado: fin de carrera derecho alcanzado!!!</translation>
    </message>
    <message>
        <source>Maximum manual speed reached: lower the speed.</source>
        <translation>Velocidad máxima alcanzada: disminuya la velocidad.</translation>
    </message>
    <message>
        <source>Program paused by the operator.</source>
        <translation>Programa pausado por el operador.</translation>
    </message>
    <message>
        <source>Program resumed.</source>
        <translation>Programa reanudado.</translation>
    </message>
    <message>
        <source>Program stopped by the operator.</source>
        <translation>Programa detenido por el operador.</translation>
    </message>
    <message>
        <source>Continue pressed.</source>
        <translation>Tecla Continuar pulsada.</translation>
    </message>
    <message>
        <source>%1: Single block: press Continue for the next block.</source>
        <translation>%1: Bloque a bloque: pulse Continuar para el siguiente bloque.</translation>
    </message>
    <message>
        <source>Starting from block %1.</source>
        <translation>Ejecución desde el bloque %1.</translation>
    </message>
    <message>
        <source>Alarm %2: %3</source>
        <translation>Alarma %2: %3</translation>
    </message>
    <message>
        <source>Alarm %2 acknowledged.</source>
        <translation>Alarma %2 reconocida.</translation>
    </message>
    <message>
        <source>Emergency stop reset.</source>
        <translation>Emergencia liberada.</translation>
    </message>
    <message>
        <source>Homing: driving right until the centre mark or the right end switch.</source>
        <translation>Referencia: hacia la derecha hasta la marca central o el final de carrera derecho.</translation>
    </message>
    <message>
        <source>Homing: on the centre mark; leaving it to the right first.</source>
        <translation>Referencia: sobre la marca central; saliendo de ella hacia la derecha primero.</translation>
    </message>
    <message>
        <source>Homing: right end switch reached; driving left to the centre mark.</source>
        <translation>Referencia: final de carrera derecho alcanzado; hacia la izquierda hasta la marca central.</translation>
    </message>
    <message>
        <source>Homing: off the centre mark; driving left back to it.</source>
        <translation>Referencia: fuera de la marca central; volviendo a la izquierda hasta ella.</translation>
    </message>
    <message>
        <source>Homing: centre mark found; the counter is zeroed on it once the platform is still.</source>
        <translation>Referencia: marca central encontrada; el contador se pone a cero en ella cuando la plataforma se detenga.</translation>
    </message>
    <message>
        <source>Homing: driving to x = 0, the rail centre.</source>
        <translation>Referencia: yendo a x = 0, el centro del riel.</translation>
    </message>
    <message>
        <source>Homing stopped by the operator: the machine is not homed.</source>
        <translation>Referencia detenida por el operador: la máquina no está referenciada.</translation>
    </message>
    <message>
        <source>Move stopped by the operator.</source>
        <translation>Movimiento detenido por el operador.</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <source>Homing stopped</source>
        <translation>Referencia detenida</translation>
    </message>
    <message>
        <source>Move stopped</source>
        <translation>Movimiento detenido</translation>
    </message>
    <message>
        <source>Warning %2: %3</source>
        <translation>Aviso %2: %3</translation>
    </message>
    <message>
        <source>POSITIONING</source>
        <translation>POSICIONANDO</translation>
    </message>
    <message>
        <source>WAITING</source>
        <translation>ESPERANDO</translation>
    </message>
    <message>
        <source>Absolute coordinates</source>
        <translation>Coordenadas absolutas</translation>
    </message>
    <message>
        <source>Incremental coordinates</source>
        <translation>Coordenadas incrementales</translation>
    </message>
    <message>
        <source>System zero changed</source>
        <translation>Cero del sistema cambiado</translation>
    </message>
    <message>
        <source>Rail zero restored</source>
        <translation>Cero del riel restablecido</translation>
    </message>
    <message>
        <source>Feed changed</source>
        <translation>Avance cambiado</translation>
    </message>
    <message>
        <source>Press Continue</source>
        <translation>Pulse Continuar</translation>
    </message>
    <message>
        <source>Program jump</source>
        <translation>Desvío de programa</translation>
    </message>
    <message>
        <source>Program ended !</source>
        <translation>¡Programa terminado!</translation>
    </message>
    <message>
        <source>Compile error(s)!</source>
        <translation>¡Error(es) de compilación!</translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation>REFERENCIANDO</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Listo</translation>
    </message>
    <message>
        <source>PAUSED</source>
        <translation>PAUSADO</translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation>ALARMA</translation>
    </message>
    <message>
        <source>Left end of travel reached ! The end switch cut the drive. Acknowledge, then in Manual drive the platform to the right, back inside the limits.</source>
        <translation>¡Fin de carrera izquierdo alcanzado! El final de carrera cortó el accionamiento. Reconozca y, en Manual, lleve la plataforma hacia la derecha, de vuelta dentro de los límites.</translation>
    </message>
    <message>
        <source>Right end of travel reached ! The end switch cut the drive. Acknowledge, then in Manual drive the platform to the left, back inside the limits.</source>
        <translation>¡Fin de carrera derecho alcanzado! El final de carrera cortó el accionamiento. Reconozca y, en Manual, lleve la plataforma hacia la izquierda, de vuelta dentro de los límites.</translation>
    </message>
    <message>
        <source>Following error: the platform did not follow the command (a jam, too heavy a load or a broken encoder cable) and the drive was cut. Free the rail, acknowledge, then home again with Automatic.</source>
        <translation>Error de seguimiento: la plataforma no siguió la orden (un atasco, una carga demasiado pesada o un cable del encoder roto) y se cortó el accionamiento. Libere el riel, reconozca y vuelva a referenciar con Automático.</translation>
    </message>
    <message>
        <source>Soft limit reached at x=%1 mm: the platform stopped there. Move it back the other way, inside the limits.</source>
        <translation>Límite de software alcanzado en x=%1 mm: la plataforma se detuvo allí. Llévela de vuelta en el sentido opuesto, dentro de los límites.</translation>
    </message>
    <message>
        <source>The program has compile errors: nothing moved. Correct the lines the diagnostics name, then run it again.</source>
        <translation>El programa tiene errores de compilación: nada se movió. Corrija las líneas que señalan los diagnósticos y ejecútelo de nuevo.</translation>
    </message>
    <message>
        <source>Encoder fault: the counter gave implausible readings again and again, and the drive was cut. Check the encoder and its cable, acknowledge, then home again with Automatic.</source>
        <translation>Falla del encoder: el contador dio lecturas imposibles una y otra vez y se cortó el accionamiento. Revise el encoder y su cable, reconozca y vuelva a referenciar con Automático.</translation>
    </message>
    <message>
        <source>Amplifier fault: the amplifier reported it is not ready and the drive was cut. Check its power, fuse and temperature, acknowledge, then home again with Automatic.</source>
        <translation>Falla del amplificador: el amplificador indicó que no está listo y se cortó el accionamiento. Revise su alimentación, su fusible y su temperatura, reconozca y vuelva a referenciar con Automático.</translation>
    </message>
    <message>
        <source>Control interrupted: the computer ran the position control too late, so the drive was cut for safety. Close other heavy programs, acknowledge, then home again with Automatic.</source>
        <translation>Control interrumpido: el equipo ejecutó el control de posición con retraso, por eso se cortó el accionamiento por seguridad. Cierre otros programas pesados, reconozca y vuelva a referenciar con Automático.</translation>
    </message>
    <message>
        <source>Emergency stop: the drive was cut. Clear the cause, then press Reset E-stop.</source>
        <translation>Parada de emergencia: se cortó el accionamiento. Elimine la causa y pulse Liberar emergencia.</translation>
    </message>
    <message>
        <source>Homing failed: the centre switch was not found. Check the switch and its cable, acknowledge, then home again with Automatic.</source>
        <translation>Referenciado fallido: no se encontró el interruptor central. Revise el interruptor y su cable, reconozca y vuelva a referenciar con Automático.</translation>
    </message>
    <message>
        <source>Soft limit: the platform would have passed the soft limit at x=%1 mm and was stopped before the end switch. Acknowledge, then move it back inside the limits.</source>
        <translation>Límite de software: la plataforma habría pasado el límite de software en x=%1 mm y se detuvo antes del final de carrera. Reconozca y llévela de vuelta dentro de los límites.</translation>
    </message>
    <message>
        <source>Not in position: the platform did not settle on its target (%1 mm off). Check the payload and the gains, acknowledge, then run again.</source>
        <translation>Fuera de posición: la plataforma no se asentó en su destino (a %1 mm). Revise la carga y las ganancias, reconozca y ejecute de nuevo.</translation>
    </message>
    <message>
        <source>The program ended with the platform %1 mm from its last target, outside the final-position window. Check the payload and the gains, then run it again.</source>
        <translation>El programa terminó con la plataforma a %1 mm de su último destino, fuera de la ventana de posición final. Revise la carga y las ganancias y ejecútelo de nuevo.</translation>
    </message>
    <message>
        <source>The centre mark corrected the position by %1 mm: counts were lost or the cable slipped. The position is right again; if this repeats, check the encoder and its cable.</source>
        <translation>La marca central corrigió la posición en %1 mm: se perdieron cuentas o el cable patinó. La posición vuelve a ser correcta; si se repite, revise el encoder y su cable.</translation>
    </message>
    <message>
        <source>Motionless loop: the program repeats blocks that neither move nor wait. It is held: press Stop, or Continue to run it again.</source>
        <translation>Bucle sin movimiento: el programa repite bloques que ni mueven ni esperan. Está retenido: pulse Detener, o Continuar para ejecutarlo de nuevo.</translation>
    </message>
    <message>
        <source>Encoder stalled: the drive ran %1 mm without a single count and was cut. Check the encoder and its cable, acknowledge, then home again.</source>
        <translation>Encoder detenido: el accionamiento comandó %1 mm sin una sola cuenta y se cortó. Revise el encoder y su cable, reconozca y vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Over-current: a motor drew too much current at %1 % PWM and its drive was cut. Free the axis, acknowledge, then home again.</source>
        <translation>Sobrecorriente: un motor consumió demasiada corriente a %1 % de PWM y se cortó su accionamiento. Libere el eje, reconozca y luego vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Steps lost: homing found the origin %1 mm from where the counted steps put it. Lower the speed, acknowledge, then home again.</source>
        <translation>Pasos perdidos: la referencia encontró el origen a %1 mm de donde lo ponían los pasos contados. Reduzca la velocidad, reconozca y luego vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Homing failed: the origin sensor was not found. Check the sensor and its cable, acknowledge, then home again.</source>
        <translation>La referencia falló: no se encontró el sensor de origen. Revise el sensor y su cable, reconozca y luego vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Link to the device lost: it did not answer, the line was too noisy, or the cable was pulled. The run is held: check the cable and the port, then press Continue to go on from the first point not acknowledged.</source>
        <translation>Enlace con el dispositivo perdido: no respondió, la línea tenía demasiado ruido o se desconectó el cable. La ejecución está suspendida: revise el cable y el puerto, luego pulse Continuar para seguir desde el primer punto no confirmado.</translation>
    </message>
    <message>
        <source>Counts lost: the count differs by %1 mm from the travel the drive made, so the position is wrong and the drive was cut. Lower the speed or check the encoder and its counter card, acknowledge, then home again.</source>
        <translation>Cuentas perdidas: la cuenta difiere en %1 mm del recorrido que hizo el accionamiento, la posición es errónea y se cortó el accionamiento. Reduzca la velocidad o revise el encoder y la tarjeta contadora, reconozca y vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Runaway: seed 004&apos;s law drove an axis on, away from its set point (it acts on |e| with the direction fixed for the move, so an axis past its set point is driven further), and the drives were cut at the soft limit at %1 mm. Acknowledge, then move it back inside the limits.</source>
        <translation>Embalamiento: la ley de la semilla 004 llevó un eje adelante, lejos de su punto de consigna (actúa sobre |e| con el sentido fijado para el movimiento, así que un eje que pasa su punto de consigna es llevado aún más lejos), y se cortaron los accionamientos en el límite de software en %1 mm. Reconozca y llévela de vuelta dentro de los límites.</translation>
    </message>
    <message>
        <source>Move refused: seed 004&apos;s board would plan %1 samples for it and its arrays hold 480 (2.4 s). Its final-time formula counts forward moves only, so a return of more than 75 mm makes the count wrap to tens of thousands. Nothing was sent. Acknowledge, then give the move in shorter steps.</source>
        <translation>Movimiento rechazado: la placa del seed 004 planificaría %1 muestras para él y sus arreglos guardan 480 (2,4 s). Su fórmula del tiempo final solo cuenta movimientos hacia adelante, y un retorno de más de 75 mm hace que la cuenta dé la vuelta a decenas de miles. No se envió nada. Reconozca y dé el movimiento en pasos más cortos.</translation>
    </message>
    <message>
        <source>%1: Travel to x=%2 y=%4 at maximum speed.</source>
        <translation>%1: Desplazamiento a x=%2 y=%4 a velocidad máxima.</translation>
    </message>
    <message>
        <source>%1: Line to x=%2 y=%4 at %3% of maximum speed.</source>
        <translation>%1: Línea hasta x=%2 y=%4 al %3% de la velocidad máxima.</translation>
    </message>
    <message>
        <source>Homing: going to the origin.</source>
        <translation>Referencia: yendo al origen.</translation>
    </message>
    <message>
        <source>Homing done: at the origin.</source>
        <translation>Referencia terminada: en el origen.</translation>
    </message>
    <message>
        <source>Homing: the table does not move; its origin is where it stood at power-on.</source>
        <translation>Referencia: la mesa no se mueve; su origen es donde estaba al encenderla.</translation>
    </message>
    <message>
        <source>Homing done: the table stands at x=%2 y=%4 from its power-on origin.</source>
        <translation>Referencia terminada: la mesa está en x=%2 y=%4 del origen al encenderla.</translation>
    </message>
    <message>
        <source>Program sent: every set point went to the board, which confirms nothing (seed 004&apos;s own firmware). The position shown is the planned one.</source>
        <translation>Programa enviado: todos los set points fueron a la placa, que no confirma nada (el firmware del propio seed 004). La posición mostrada es la planificada.</translation>
    </message>
    <message>
        <source>%1: Return to the machine&apos;s absolute zero.</source>
        <translation>%1: Regreso al cero absoluto de la máquina.</translation>
    </message>
    <message>
        <source>Lower end of travel of the table reached ! An end switch cut the drives. Acknowledge, then in Manual drive the table back inside the limits.</source>
        <translation>¡Fin de carrera inferior de la mesa alcanzado! Un final de carrera cortó los accionamientos. Reconozca y, en Manual, lleve la mesa de vuelta dentro de los límites.</translation>
    </message>
    <message>
        <source>Upper end of travel of the table reached ! An end switch cut the drives. Acknowledge, then in Manual drive the table back inside the limits.</source>
        <translation>¡Fin de carrera superior de la mesa alcanzado! Un final de carrera cortó los accionamientos. Reconozca y, en Manual, lleve la mesa de vuelta dentro de los límites.</translation>
    </message>
    <message>
        <source>Following error: an axis of the table (x or y) was %1 mm behind the command (a jam, too heavy a load or a broken encoder cable) and both drives were cut. Free the table, acknowledge, then home again.</source>
        <translation>Error de seguimiento: un eje de la mesa (x o y) quedó %1 mm detrás de la orden (un atasco, una carga demasiado pesada o un cable del encoder roto) y se cortaron ambos accionamientos. Libere la mesa, reconozca y vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Soft limit: the target is outside the table&apos;s travel, so the table stopped at its limit. Move it back the other way, inside the limits.</source>
        <translation>Límite de software: el destino está fuera del recorrido de la mesa, y la mesa se detuvo en su límite. Llévela de vuelta en el sentido opuesto, dentro de los límites.</translation>
    </message>
    <message>
        <source>Homing failed: the table&apos;s origin was not found. Check its sensor and cable, acknowledge, then home again.</source>
        <translation>Referenciado fallido: no se encontró el origen de la mesa. Revise el sensor y su cable, reconozca y vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Soft limit: the table would have passed the soft limit of its x or y axis at %1 mm and was stopped. Acknowledge, then move it back inside the limits.</source>
        <translation>Límite de software: la mesa habría pasado el límite de software de su eje x o y en %1 mm y se detuvo. Reconozca y llévela de vuelta dentro de los límites.</translation>
    </message>
    <message>
        <source>Not in position: the table did not settle on its target (%1 mm off on its x or y axis). Check the payload and the gains, acknowledge, then run again.</source>
        <translation>Fuera de posición: la mesa no se asentó en su destino (a %1 mm en el eje x o y). Revise la carga y las ganancias, reconozca y ejecute de nuevo.</translation>
    </message>
    <message>
        <source>The program ended with the table %1 mm from its last target on its x or y axis, outside the final-position window. Check the payload and the gains, then run it again.</source>
        <translation>El programa terminó con la mesa a %1 mm de su último destino en el eje x o y, fuera de la ventana de posición final. Revise la carga y las ganancias y ejecútelo de nuevo.</translation>
    </message>
    <message>
        <source>A reference mark corrected the table&apos;s position by %1 mm: counts were lost or a belt slipped. The position is right again; if this repeats, check the encoders and their cables.</source>
        <translation>Una marca de referencia corrigió la posición de la mesa en %1 mm: se perdieron cuentas o una correa patinó. La posición vuelve a ser correcta; si se repite, revise los encoders y sus cables.</translation>
    </message>
    <message>
        <source>Encoder stalled: a drive of the table (x or y axis) ran %1 mm without a single count and both drives were cut. Check the encoder and its cable, acknowledge, then home again.</source>
        <translation>Encoder detenido: un accionamiento de la mesa (eje x o y) recorrió %1 mm sin una sola cuenta y se cortaron los accionamientos. Revise el encoder y su cable, reconozca y vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Over-current: a motor of the table (x or y axis) drew too much current at %1 % PWM and the drives were cut. Free the axis, acknowledge, then home again.</source>
        <translation>Sobrecorriente: un motor de la mesa (eje x o y) consumió demasiada corriente a %1 % de PWM y se cortaron los accionamientos. Libere el eje, reconozca y vuelva a referenciar.</translation>
    </message>
    <message>
        <source>Runaway: seed 004&apos;s law drove an axis of the table (x or y) on, away from its set point: it acts on |e| with the direction fixed for the move, so an axis that passes its set point is driven further. Both drives were cut at the soft limit at %1 mm. Acknowledge, then move the table back inside the limits (the seed-signed and engineered laws drive back instead).</source>
        <translation>Embalamiento: la ley de la semilla 004 llevó un eje de la mesa (x o y) adelante, lejos de su punto de consigna: actúa sobre |e| con el sentido fijado para el movimiento, así que un eje que pasa su punto de consigna es llevado aún más lejos. Se cortaron ambos accionamientos en el límite de software en %1 mm. Reconozca y lleve la mesa de vuelta dentro de los límites (las leyes seed-signed y engineered la traen de vuelta).</translation>
    </message>
</context>
<context>
    <name>Diagnostic</name>
    <message>
        <source>every line must start with n (found &apos;%2&apos;)</source>
        <translation>toda línea debe comenzar con n (se encontró &apos;%2&apos;)</translation>
    </message>
    <message>
        <source>wrong n sequence %1: must be greater than %3</source>
        <translation>secuencia n incorrecta %1: debe ser mayor que %3</translation>
    </message>
    <message>
        <source>sequence number alone %1</source>
        <translation>número de secuencia solo %1</translation>
    </message>
    <message>
        <source>separating spaces required %1 (found &apos;%2&apos;)</source>
        <translation>se requieren espacios de separación %1 (se encontró &apos;%2&apos;)</translation>
    </message>
    <message>
        <source>there can be no more commands after %2 %1</source>
        <translation>no puede haber más comandos después de %2 %1</translation>
    </message>
    <message>
        <source>g00 requires an x word %1</source>
        <translation>g00 requiere comando x %1</translation>
    </message>
    <message>
        <source>g01 requires an x word %1</source>
        <translation>g01 requiere comando x %1</translation>
    </message>
    <message>
        <source>g04 without x word (time) %1</source>
        <translation>g04 sin comando x (tiempo) %1</translation>
    </message>
    <message>
        <source>g92 requires an x word %1</source>
        <translation>g92 requiere comando x %1</translation>
    </message>
    <message>
        <source>m03 without x word (block) %1</source>
        <translation>m03 sin comando x (bloque) %1</translation>
    </message>
    <message>
        <source>invalid value after g04 %1: the time %2 is negative</source>
        <translation>valor inválido después de g04 %1: el tiempo %2 es negativo</translation>
    </message>
    <message>
        <source>invalid value after m03 %1: the block %2 is negative</source>
        <translation>valor inválido después de m03 %1: el bloque %2 es negativo</translation>
    </message>
    <message>
        <source>negative f command impossible %1 (%2)</source>
        <translation>comando f negativo imposible %1 (%2)</translation>
    </message>
    <message>
        <source>invalid g command %1 (%2)</source>
        <translation>comando g inválido %1 (%2)</translation>
    </message>
    <message>
        <source>invalid m command %1 (%2)</source>
        <translation>comando m inválido %1 (%2)</translation>
    </message>
    <message>
        <source>g01 or g00 not defined %1</source>
        <translation>g01 o g00 no definidos %1</translation>
    </message>
    <message>
        <source>g01 needs f defined %1</source>
        <translation>g01 necesita f definido %1</translation>
    </message>
    <message>
        <source>invalid character or g00 does not take f %1</source>
        <translation>carácter inválido o g00 no admite f %1</translation>
    </message>
    <message>
        <source>invalid character %1: &apos;%2&apos;</source>
        <translation>carácter inválido %1: &apos;%2&apos;</translation>
    </message>
    <message>
        <source>invalid character %1: malformed number &apos;%2&apos;</source>
        <translation>carácter inválido %1: número mal formado &apos;%2&apos;</translation>
    </message>
    <message>
        <source>invalid character %1: &apos;%2&apos; must have exactly %3 digits</source>
        <translation>carácter inválido %1: &apos;%2&apos; debe tener exactamente %3 dígitos</translation>
    </message>
    <message>
        <source>invalid character %1: comment not closed</source>
        <translation>carácter inválido %1: comentario sin cerrar</translation>
    </message>
    <message>
        <source>invalid character %1: word &apos;%2&apos; repeated</source>
        <translation>carácter inválido %1: palabra &apos;%2&apos; repetida</translation>
    </message>
    <message>
        <source>invalid character %1: n must be the first word (&apos;%2&apos;)</source>
        <translation>carácter inválido %1: n debe ser la primera palabra (&apos;%2&apos;)</translation>
    </message>
    <message>
        <source>invalid value after m03 %1: &apos;%2&apos; is not a block number</source>
        <translation>valor inválido después de m03 %1: &apos;%2&apos; no es un número de bloque</translation>
    </message>
    <message>
        <source>invalid character %1: number &apos;%2&apos; longer than %3 digits</source>
        <translation>carácter inválido %1: número &apos;%2&apos; de más de %3 dígitos</translation>
    </message>
    <message>
        <source>program requires m02 (END) at the end</source>
        <translation>el programa requiere m02 (END) al final</translation>
    </message>
    <message>
        <source>invalid GO TO %1: block n=%2 does not exist</source>
        <translation>GO TO inválido %1: el bloque n=%2 no existe</translation>
    </message>
    <message>
        <source>feed f%2 out of range %1: must be from %3 % to 100 %</source>
        <translation>avance f%2 fuera de rango %1: debe estar entre %3 % y 100 %</translation>
    </message>
    <message>
        <source>target %2 mm %1 is beyond the soft limit %3 mm</source>
        <translation>destino %2 mm %1 más allá del límite de recorrido %3 mm</translation>
    </message>
    <message>
        <source>axis %2 %1 does not exist on this machine</source>
        <translation>el eje %2 %1 no existe en esta máquina</translation>
    </message>
    <message>
        <source>block number &apos;%2&apos; too large %1: at most %3</source>
        <translation>número de bloque &apos;%2&apos; demasiado grande %1: como máximo %3</translation>
    </message>
    <message>
        <source>value &apos;%2&apos; too large %1: at most %3 in magnitude</source>
        <translation>valor &apos;%2&apos; demasiado grande %1: como máximo %3 en valor absoluto</translation>
    </message>
    <message>
        <source>in line n=%1</source>
        <translation>en la línea n=%1</translation>
    </message>
    <message>
        <source>in block n=%1</source>
        <translation>en el bloque n=%1</translation>
    </message>
    <message>
        <source>on line %1</source>
        <translation>en la línea %1</translation>
    </message>
    <message>
        <source>Compilation completed successfully</source>
        <translation>Compilación completada con éxito</translation>
    </message>
    <message>
        <source>%1 compile error(s)</source>
        <translation>%1 error(es) de compilación</translation>
    </message>
    <message>
        <source>... and %1 more diagnostic(s) not listed</source>
        <translation>... y %1 diagnóstico(s) más no listado(s)</translation>
    </message>
</context>
<context>
    <name>JournalNotice</name>
    <message>
        <source>The history is kept by another trilho (pid %1 on %2): this one writes %3.</source>
        <translation>El historial lo lleva otro trilho (pid %1 en %2): este escribe %3.</translation>
    </message>
    <message>
        <source>The history is kept by another trilho: this one writes %1.</source>
        <translation>El historial lo lleva otro trilho: este escribe %1.</translation>
    </message>
    <message>
        <source>The screens started %1 (%2) stopped without their end mark: they were killed, crashed or lost power.</source>
        <translation>Las pantallas iniciadas el %1 (%2) se detuvieron sin su marca de fin: se las mató, fallaron o se quedaron sin energía.</translation>
    </message>
</context>
<context>
    <name>PreRunCheckText</name>
    <message>
        <source>during homing</source>
        <translation>durante la referencia</translation>
    </message>
    <message>
        <source>on the way to the program&apos;s start</source>
        <translation>en el camino al inicio del programa</translation>
    </message>
    <message>
        <source>at line %1</source>
        <translation>en la línea %1</translation>
    </message>
    <message>
        <source>warning %1 (%2) %3</source>
        <translation>aviso %1 (%2) %3</translation>
    </message>
    <message>
        <source>alarm %1 (%2) %3</source>
        <translation>alarma %1 (%2) %3</translation>
    </message>
    <message>
        <source>no end within %1 s of machine time (a loop without end, a long dwell or a longer program)</source>
        <translation>sin fin en %1 s de tiempo de máquina (un bucle sin fin, una espera larga o un programa más largo)</translation>
    </message>
    <message>
        <source>no end within %1 s of machine time: the feed override is at 0 %, nothing moves</source>
        <translation>sin fin en %1 s de tiempo de máquina: la corrección de avance está en 0 %, nada se mueve</translation>
    </message>
    <message>
        <source>%1 goes %2 mm beyond its soft limits %3</source>
        <translation>%1 pasa %2 mm más allá de sus límites de software %3</translation>
    </message>
    <message>
        <source>Pre-run check: %1.</source>
        <translation>Verificación previa: %1.</translation>
    </message>
    <message>
        <source>Pre-run check: cycle %1 s, worst following error %2 mm at line %3.</source>
        <translation>Verificación previa: ciclo de %1 s, mayor error de seguimiento %2 mm en la línea %3.</translation>
    </message>
    <message>
        <source>Pre-run check: cycle %1 s, worst following error %2 mm.</source>
        <translation>Verificación previa: ciclo de %1 s, mayor error de seguimiento %2 mm.</translation>
    </message>
    <message>
        <source>Pre-run check: still running.</source>
        <translation>Verificación previa: todavía en curso.</translation>
    </message>
    <message>
        <source>Pre-run check: not possible (see the details).</source>
        <translation>Verificación previa: no fue posible (vea los detalles).</translation>
    </message>
    <message>
        <source>The pre-run check of %1 could not run: %2</source>
        <translation>La verificación previa de %1 no pudo hacerse: %2</translation>
    </message>
    <message>
        <source>Pre-run check of %1: ok.</source>
        <translation>Verificación previa de %1: ok.</translation>
    </message>
    <message>
        <source>Pre-run check of %1: NOT OK: %2.</source>
        <translation>Verificación previa de %1: NO OK: %2.</translation>
    </message>
    <message>
        <source>It ran on the simulated rail of the profile %1, in virtual time from homing, with the %2 (Kp %3, Ki %4, Kd %5) and the feed override at %6 %, as Cycle start runs it now.</source>
        <translation>Hecha en el riel simulado del perfil %1, en tiempo virtual desde la referencia, con la %2 (Kp %3, Ki %4, Kd %5) y la corrección de avance en %6 %, como el Inicio de ciclo lo ejecuta ahora.</translation>
    </message>
    <message>
        <source>classic law</source>
        <translation>ley clásica</translation>
    </message>
    <message>
        <source>engineered law</source>
        <translation>ley moderna</translation>
    </message>
    <message>
        <source>It ran on the simulated machine of the profile %1, in virtual time from homing, with the feed override at %2 %, as Cycle start runs it now.</source>
        <translation>Hecha en la máquina simulada del perfil %1, en tiempo virtual desde la referencia, con la corrección de avance en %2 %, como el Inicio de ciclo lo ejecuta ahora.</translation>
    </message>
    <message>
        <source>An m00 is continued at once (the operator&apos;s wait is not in the cycle time); the Simulation dock&apos;s faults are not in it.</source>
        <translation>Un m00 se continúa de inmediato (la espera del operador no entra en el tiempo de ciclo); las fallas del panel Simulación no entran en ella.</translation>
    </message>
    <message>
        <source>Cycle time: unknown, still running after %1 s of machine time (the screens&apos; bound).</source>
        <translation>Tiempo de ciclo: desconocido, todavía en curso tras %1 s de tiempo de máquina (el límite de las pantallas).</translation>
    </message>
    <message>
        <source>Cycle time: none, the program never started (homing did not end).</source>
        <translation>Tiempo de ciclo: ninguno, el programa no empezó (la referencia no terminó).</translation>
    </message>
    <message>
        <source>Cycle time: %1 s from the program&apos;s start (after %2 s of homing).</source>
        <translation>Tiempo de ciclo: %1 s desde el inicio del programa (tras %2 s de referencia).</translation>
    </message>
    <message>
        <source>Cycle time: %1 s from the program&apos;s start to where it stopped (after %2 s of homing).</source>
        <translation>Tiempo de ciclo: %1 s desde el inicio del programa hasta donde se detuvo (tras %2 s de referencia).</translation>
    </message>
    <message>
        <source>Envelope %1: %2 to %3 mm (soft limits %4 to %5 mm)</source>
        <translation>Envolvente %1: %2 a %3 mm (límites de software %4 a %5 mm)</translation>
    </message>
    <message>
        <source>%1, OUTSIDE by %2 mm %3.</source>
        <translation>%1, FUERA por %2 mm %3.</translation>
    </message>
    <message>
        <source>Worst following error: %1 mm on %2 %3, %4 s into the cycle.</source>
        <translation>Mayor error de seguimiento: %1 mm en %2 %3, %4 s tras el inicio del ciclo.</translation>
    </message>
    <message>
        <source>Worst following error: 0 mm.</source>
        <translation>Mayor error de seguimiento: 0 mm.</translation>
    </message>
    <message>
        <source>Longest saturation of the drive: not modelled (the plotter&apos;s steppers have no drive level).</source>
        <translation>Mayor saturación del accionamiento: no modelada (los motores paso a paso del plotter no tienen nivel de accionamiento).</translation>
    </message>
    <message>
        <source>Longest saturation of the drive: %1 s %2, %3 s into the cycle.</source>
        <translation>Mayor saturación del accionamiento: %1 s %2, %3 s tras el inicio del ciclo.</translation>
    </message>
    <message>
        <source>Longest saturation of the drive: none.</source>
        <translation>Mayor saturación del accionamiento: ninguna.</translation>
    </message>
    <message>
        <source>Alarms: none.</source>
        <translation>Alarmas: ninguna.</translation>
    </message>
    <message>
        <source>Warning %1 %2: %3</source>
        <translation>Aviso %1 %2: %3</translation>
    </message>
    <message>
        <source>Alarm %1 %2: %3</source>
        <translation>Alarma %1 %2: %3</translation>
    </message>
    <message>
        <source>... and %1 more.</source>
        <translation>... y %1 más.</translation>
    </message>
    <message>
        <source>m00: %1 stop(s) continued at once.</source>
        <translation>m00: %1 parada(s) continuada(s) de inmediato.</translation>
    </message>
</context>
<context>
    <name>trilho</name>
    <message>
        <source>a verification move with the tuned gains was stopped by an alarm: %1</source>
        <translation>un movimiento de verificación con las ganancias sintonizadas fue detenido por una alarma: %1</translation>
    </message>
    <message>
        <source>a verification move with the tuned gains did not end in position</source>
        <translation>un movimiento de verificación con las ganancias sintonizadas no terminó en posición</translation>
    </message>
    <message>
        <source>the experiment recorded too little</source>
        <translation>el experimento registró muy pocos datos</translation>
    </message>
    <message>
        <source>the model fits the held-out run at %1 % on velocity, under %2 %</source>
        <translation>el modelo ajusta el ensayo de validación al %1 % en velocidad, por debajo del %2 %</translation>
    </message>
    <message>
        <source>the experiment needs %1 mm each side of its start inside the soft limits [%2, %3] mm; the axis is at %4 mm</source>
        <translation>el experimento necesita %1 mm a cada lado de su inicio dentro de los límites de software [%2, %3] mm; el eje está en %4 mm</translation>
    </message>
    <message>
        <source>the table refused the drive (a limit, an alarm)</source>
        <translation>la mesa rechazó el accionamiento (un límite, una alarma)</translation>
    </message>
    <message>
        <source>the experiment was stopped by an alarm: %1</source>
        <translation>el experimento fue detenido por una alarma: %1</translation>
    </message>
    <message>
        <source>the axis left the experiment&apos;s +-100 mm or its soft limits</source>
        <translation>el eje salió de los +-100 mm del experimento o de los límites de software</translation>
    </message>
    <message>
        <source>the return to the start was stopped by an alarm: %1</source>
        <translation>el regreso al inicio fue detenido por una alarma: %1</translation>
    </message>
    <message>
        <source>the axis did not come back within one count of its start (%1 mm away)</source>
        <translation>el eje no volvió a menos de una cuenta de su inicio (quedó a %1 mm)</translation>
    </message>
    <message>
        <source>%1 %2 held to %3</source>
        <translation>%1 %2 limitado a %3</translation>
    </message>
    <message>
        <source>the servo refused the drive (a limit or an end switch)</source>
        <translation>el servo rechazó el accionamiento (un límite o un final de carrera)</translation>
    </message>
    <message>
        <source>the platform left the experiment&apos;s +-100 mm</source>
        <translation>la plataforma salió de los +-100 mm del experimento</translation>
    </message>
    <message>
        <source>the platform did not come back within one count of its start (%1 mm away)</source>
        <translation>la plataforma no volvió a menos de una cuenta de su inicio (quedó a %1 mm)</translation>
    </message>
    <message>
        <source>the relay cycle left the experiment&apos;s +-100 mm</source>
        <translation>el ciclo del relé salió de los +-100 mm del experimento</translation>
    </message>
    <message>
        <source>the relay did not oscillate (%1 switches in %2 s)</source>
        <translation>el relé no osciló (%1 conmutaciones en %2 s)</translation>
    </message>
    <message>
        <source>the relay cycle was too short to time</source>
        <translation>el ciclo del relé fue demasiado corto para medirlo</translation>
    </message>
    <message>
        <source>the relay cycle had no amplitude</source>
        <translation>el ciclo del relé no tuvo amplitud</translation>
    </message>
    <message>
        <source>no fault</source>
        <translation>sin falla</translation>
    </message>
    <message>
        <source>following error</source>
        <translation>error de seguimiento</translation>
    </message>
    <message>
        <source>left end switch</source>
        <translation>final de carrera izquierdo</translation>
    </message>
    <message>
        <source>right end switch</source>
        <translation>final de carrera derecho</translation>
    </message>
    <message>
        <source>amplifier fault</source>
        <translation>falla del amplificador</translation>
    </message>
    <message>
        <source>hard stop</source>
        <translation>tope mecánico</translation>
    </message>
    <message>
        <source>soft limit</source>
        <translation>límite de software</translation>
    </message>
    <message>
        <source>encoder stalled</source>
        <translation>encoder detenido</translation>
    </message>
    <message>
        <source>in-position timeout</source>
        <translation>tiempo agotado para llegar a posición</translation>
    </message>
    <message>
        <source>counts lost</source>
        <translation>cuentas perdidas</translation>
    </message>
    <message>
        <source>late ticks</source>
        <translation>ticks retrasados</translation>
    </message>
    <message>
        <source>unknown fault</source>
        <translation>falla desconocida</translation>
    </message>
</context>
<context>
    <name>trilho::SerialLine</name>
    <message>
        <source>serial port %1: %2 (was the device unplugged?)</source>
        <translation>puerto serie %1: %2 (¿se desconectó el dispositivo?)</translation>
    </message>
    <message>
        <source>cannot open serial port %1: %2</source>
        <translation>no se puede abrir el puerto serie %1: %2</translation>
    </message>
    <message>
        <source>cannot set %1 bit/s 8N1 on serial port %2: %3</source>
        <translation>no se puede configurar %1 bit/s 8N1 en el puerto serie %2: %3</translation>
    </message>
</context>
<context>
    <name>trilho::ui::CalibrationDialog</name>
    <message>
        <source>Calibration of the table</source>
        <translation>Calibración de la mesa</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>no medido</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <source>Compute</source>
        <translation>Calcular</translation>
    </message>
    <message>
        <source>Save profile...</source>
        <translation>Guardar perfil...</translation>
    </message>
    <message>
        <source>Run the board&apos;s calibration program, then press Start.</source>
        <translation>Ejecute el programa de calibración de la placa y pulse Iniciar.</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>pulses</source>
        <translation>pulsos</translation>
    </message>
    <message>
        <source>displacement (mm)</source>
        <translation>desplazamiento (mm)</translation>
    </message>
    <message>
        <source>Serial port:</source>
        <translation>Puerto serie:</translation>
    </message>
    <message>
        <source>Bit rate:</source>
        <translation>Velocidad:</translation>
    </message>
    <message>
        <source>Axis:</source>
        <translation>Eje:</translation>
    </message>
    <message>
        <source>Travel measured:</source>
        <translation>Desplazamiento medido:</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <source>Receiving the counts on %1...</source>
        <translation>Recibiendo las cuentas en %1...</translation>
    </message>
    <message>
        <source>The stream is refused, nothing to save: %1. Press Start for a new run.</source>
        <translation>El flujo fue rechazado, nada que guardar: %1. Pulse Iniciar para una nueva ejecución.</translation>
    </message>
    <message>
        <source>Nothing to save: %1</source>
        <translation>Nada que guardar: %1</translation>
    </message>
    <message>
        <source>%1 counts, %2 pulses/s; the board stopped at about %3 pulses. %4 mm per pulse, %5 mm per turn (the profile has %6).</source>
        <translation>%1 cuentas, %2 pulsos/s; la placa se detuvo en unos %3 pulsos. %4 mm por pulso, %5 mm por vuelta (el perfil tiene %6).</translation>
    </message>
    <message>
        <source>%1 counts, %2 pulses/s; the board stopped at about %3 pulses. Enter the travel measured for mm per pulse.</source>
        <translation>%1 cuentas, %2 pulsos/s; la placa se detuvo en unos %3 pulsos. Ingrese el desplazamiento medido para obtener mm por pulso.</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>Guardar perfil</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Perfiles de máquina (*.json)</translation>
    </message>
    <message>
        <source>Saved: %1</source>
        <translation>Guardado: %1</translation>
    </message>
</context>
<context>
    <name>trilho::ui::DcTablePanel</name>
    <message>
        <source>Set point</source>
        <translation>Punto de consigna</translation>
    </message>
    <message>
        <source>Send &amp;X</source>
        <translation>Enviar &amp;X</translation>
    </message>
    <message>
        <source>Send &amp;Y</source>
        <translation>Enviar &amp;Y</translation>
    </message>
    <message>
        <source>&amp;Send X and Y</source>
        <translation>&amp;Enviar X e Y</translation>
    </message>
    <message>
        <source>X %1 mm sent: send Y to move.</source>
        <translation>X %1 mm enviado: envíe Y para mover.</translation>
    </message>
    <message>
        <source>Y %1 mm sent: send X to move.</source>
        <translation>Y %1 mm enviado: envíe X para mover.</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Ejecutando</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <source>Click to stop the table</source>
        <translation>Haga clic para detener la mesa</translation>
    </message>
    <message>
        <source>Click to start the table towards the set point</source>
        <translation>Haga clic para arrancar la mesa hacia el punto de consigna</translation>
    </message>
    <message>
        <source>Entry number: raise it by one before a new set point (the operator&apos;s entries, seed 004); a lower number shows an earlier entry, to send it again</source>
        <translation>Número de ingreso: auméntelo en uno antes de un nuevo set point (los ingresos del operador, seed 004); un número menor muestra un ingreso anterior, para enviarlo de nuevo</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>Puerto serie</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Puerto</translation>
    </message>
    <message>
        <source>Bit rate</source>
        <translation>Velocidad (bit/s)</translation>
    </message>
    <message>
        <source>Simulated machine</source>
        <translation>Máquina simulada</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
</context>
<context>
    <name>trilho::ui::DisturbanceView</name>
    <message>
        <source>Set the load torque and when it comes, then Run: the window&apos;s axis, law, gains, period, mass and seed are used. Try Ki 0, then Ki 40.</source>
        <translation>Defina el par de carga y cuándo llega, luego Ejecutar: se usan el eje, la ley, las ganancias, el período, la masa y la semilla de la ventana. Pruebe Ki 0, luego Ki 40.</translation>
    </message>
    <message>
        <source>Set the load and when it comes, then Run: the window&apos;s law, gains, period, mass and seed are used. Try Ki 0, then Ki 5.</source>
        <translation>Defina la carga y cuándo llega, luego Ejecutar: se usan la ley, las ganancias, el período, la masa y la semilla de la ventana. Pruebe Ki 0, luego Ki 5.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Not run:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;No ejecutado:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Aborted:&lt;/b&gt; %1&lt;br&gt;</source>
        <translation>&lt;b&gt;Interrumpido:&lt;/b&gt; %1&lt;br&gt;</translation>
    </message>
    <message>
        <source>No metrics: %1</source>
        <translation>Sin métricas: %1</translation>
    </message>
    <message>
        <source>Load %1 % of the stall torque on axis %2 at %3 s, Kp %4, Ki %5, Kff %6&lt;br&gt;</source>
        <translation>Carga del %1 % del par de arranque en el eje %2 a los %3 s, Kp %4, Ki %5, Kff %6&lt;br&gt;</translation>
    </message>
    <message>
        <source>Load %1 N at %2 s, Kp %3, Ki %4, Kd %5&lt;br&gt;</source>
        <translation>Carga %1 N a los %2 s, Kp %3, Ki %4, Kd %5&lt;br&gt;</translation>
    </message>
    <message>
        <source>Peak deviation before the stop: &lt;b&gt;%1 mm&lt;/b&gt;; no recovery and no steady state were measured</source>
        <translation>Desviación de pico antes de la parada: &lt;b&gt;%1 mm&lt;/b&gt;; no se midieron ni recuperación ni régimen</translation>
    </message>
    <message>
        <source>Peak deviation: &lt;b&gt;%1 mm&lt;/b&gt; at %2 s after the load&lt;br&gt;</source>
        <translation>Desviación de pico: &lt;b&gt;%1 mm&lt;/b&gt; %2 s después de la carga&lt;br&gt;</translation>
    </message>
    <message>
        <source>Recovery time: &lt;b&gt;%1 s&lt;/b&gt; (back within %2 mm of where it was)&lt;br&gt;</source>
        <translation>Tiempo de recuperación: &lt;b&gt;%1 s&lt;/b&gt; (de vuelta a menos de %2 mm de donde estaba)&lt;br&gt;</translation>
    </message>
    <message>
        <source>Recovery time: &lt;b&gt;not reached&lt;/b&gt; (still more than %1 mm from where it was at the end)&lt;br&gt;</source>
        <translation>Tiempo de recuperación: &lt;b&gt;no alcanzado&lt;/b&gt; (todavía a más de %1 mm de donde estaba, al final)&lt;br&gt;</translation>
    </message>
    <message>
        <source>Steady deviation: &lt;b&gt;%1 mm&lt;/b&gt; (mean of the last %2 s)&lt;br&gt;</source>
        <translation>Desviación en régimen: &lt;b&gt;%1 mm&lt;/b&gt; (media de los últimos %2 s)&lt;br&gt;</translation>
    </message>
    <message>
        <source>A PWM drive, no speed loop: with Ki 0 the loop rests about %1 mm off, where its drive less friction and a duty step meets the load, give or take friction&apos;s band</source>
        <translation>Accionamiento PWM, sin lazo de velocidad: con Ki 0 el lazo se detiene a unos %1 mm, donde su accionamiento menos la fricción y un paso de ciclo iguala la carga, más o menos la banda de la fricción</translation>
    </message>
    <message>
        <source>A PWM drive, no speed loop: the motor&apos;s back EMF is its stiffness</source>
        <translation>Accionamiento PWM, sin lazo de velocidad: la fuerza contraelectromotriz del motor es su rigidez</translation>
    </message>
    <message>
        <source>Amplifier stiffness %1 N per mm/s: with Ki 0 the loop settles where Kp&apos;s drive gives back the speed the load adds, %2 mm</source>
        <translation>Rigidez del amplificador %1 N por mm/s: con Ki 0 el lazo se asienta donde el accionamiento de Kp devuelve la velocidad que la carga añade, %2 mm</translation>
    </message>
    <message>
        <source>The amplifier is an ideal speed source: no load slows it</source>
        <translation>El amplificador es una fuente de velocidad ideal: ninguna carga lo frena</translation>
    </message>
    <message>
        <source>Load torque on the axis</source>
        <translation>Par de carga en el eje</translation>
    </message>
    <message>
        <source>Load on the platform</source>
        <translation>Carga en la plataforma</translation>
    </message>
    <message>
        <source>Load comes at</source>
        <translation>La carga llega a los</translation>
    </message>
    <message>
        <source>While</source>
        <translation>Durante</translation>
    </message>
    <message>
        <source>holding still</source>
        <translation>detenido</translation>
    </message>
    <message>
        <source>moving (10 % of rapid)</source>
        <translation>moviéndose (10 % del rápido)</translation>
    </message>
    <message>
        <source>Run load test</source>
        <translation>Ejecutar prueba de carga</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>deviation (mm)</source>
        <translation>desviación (mm)</translation>
    </message>
    <message>
        <source>load (% of stall torque)</source>
        <translation>carga (% del par de arranque)</translation>
    </message>
    <message>
        <source>load (N)</source>
        <translation>carga (N)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::DncDialog</name>
    <message>
        <source>Programs folder</source>
        <translation>Carpeta de los programas</translation>
    </message>
    <message>
        <source>The address &apos;%1&apos; is not an IP address: write a numeric address such as 127.0.0.1 (this computer only), or 0.0.0.0 for every network interface.</source>
        <translation>La dirección &apos;%1&apos; no es una dirección IP: escriba una dirección numérica como 127.0.0.1 (solo este ordenador) o 0.0.0.0 para todas las interfaces de red.</translation>
    </message>
    <message>
        <source>The port must be a whole number from 1 to 65535 (got &apos;%1&apos;); Modbus TCP&apos;s own is 502, which needs administrator rights: 1502 does not.</source>
        <translation>El puerto debe ser un número entero de 1 a 65535 (recibido &apos;%1&apos;); el de Modbus TCP es 502, que requiere derechos de administrador: 1502 no.</translation>
    </message>
    <message>
        <source>Modbus RTU needs the serial device, e.g. /dev/ttyUSB0 (or turn RTU off).</source>
        <translation>Modbus RTU necesita el dispositivo serie, p. ej. /dev/ttyUSB0 (o desactive RTU).</translation>
    </message>
    <message>
        <source>The DNC settings could not be saved to %1 (a full disk or a folder that cannot be written): they hold until trilho closes.</source>
        <translation>La configuración del DNC no pudo guardarse en %1 (disco lleno o carpeta sin permiso de escritura): vale hasta que trilho se cierre.</translation>
    </message>
    <message>
        <source>Warning: %1 can be reached from other computers. Modbus has no password and no encryption: anyone on that network can read this machine and, while Remote is on, change its gains and run programs. Use 127.0.0.1 unless the cell&apos;s network is closed.</source>
        <translation>Atención: %1 es accesible desde otros ordenadores. Modbus no tiene contraseña ni cifrado: cualquiera en esa red puede leer esta máquina y, con Remoto activado, cambiar sus ganancias y ejecutar programas. Use 127.0.0.1 salvo que la red de la célula sea cerrada.</translation>
    </message>
    <message>
        <source>DNC: off</source>
        <translation>DNC: desactivado</translation>
    </message>
    <message>
        <source>DNC link (Modbus)</source>
        <translation>Enlace DNC (Modbus)</translation>
    </message>
    <message>
        <source>Serve the DNC link (Modbus) for the cell&apos;s supervisor</source>
        <translation>Servir el enlace DNC (Modbus) para el supervisor de la célula</translation>
    </message>
    <message>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <source>Address:</source>
        <translation>Dirección:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Puerto:</translation>
    </message>
    <message>
        <source>Modbus RTU on a serial line (8N1)</source>
        <translation>Modbus RTU en una línea serie (8N1)</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Dispositivo:</translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation>Baudios:</translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation>Unidad (id):</translation>
    </message>
    <message>
        <source>Program library</source>
        <translation>Biblioteca</translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation>Carpeta:</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <source>Reading is always allowed. Writes and commands need Remote (Options &gt; Remote, Ctrl+Shift+R), which is off at every start.</source>
        <translation>La lectura siempre está permitida. Escrituras y comandos requieren Remoto (Opciones &gt; Remoto, Ctrl+Shift+R), que está desactivado en cada inicio.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::DncLink</name>
    <message>
        <source>Cannot listen on %1:%2: %3. Another program (another trilho?) may be using this port: choose another port or stop that program.</source>
        <translation>No se puede escuchar en %1:%2: %3. Otro programa (¿otro trilho?) puede estar usando este puerto: elija otro puerto o cierre ese programa.</translation>
    </message>
    <message>
        <source>DNC: cannot listen on %1:%2 (port taken?)</source>
        <translation>DNC: no escucha en %1:%2 (¿puerto ocupado?)</translation>
    </message>
    <message>
        <source>Cannot open the serial device %1 for Modbus RTU: %2</source>
        <translation>No se puede abrir el dispositivo serie %1 para Modbus RTU: %2</translation>
    </message>
    <message>
        <source>DNC: cannot open %1</source>
        <translation>DNC: no se puede abrir %1</translation>
    </message>
    <message>
        <source>DNC: %1</source>
        <translation>DNC: %1</translation>
    </message>
    <message>
        <source>DNC: %1, %2, %3</source>
        <translation>DNC: %1, %2, %3</translation>
    </message>
    <message>
        <source>Remote ON</source>
        <translation>Remoto ACTIVADO</translation>
    </message>
    <message>
        <source>Remote off</source>
        <translation>Remoto desactivado</translation>
    </message>
    <message>
        <source>1 client</source>
        <translation>1 cliente</translation>
    </message>
    <message>
        <source>%1 clients</source>
        <translation>%1 clientes</translation>
    </message>
</context>
<context>
    <name>trilho::ui::DroPanel</name>
    <message>
        <source>Machine X</source>
        <translation>X máquina</translation>
    </message>
    <message>
        <source>To go</source>
        <translation>Falta</translation>
    </message>
    <message>
        <source>Program X</source>
        <translation>X programa</translation>
    </message>
    <message>
        <source>zero %1 mm</source>
        <translation>cero %1 mm</translation>
    </message>
    <message>
        <source>F %1 %</source>
        <translation>F %1 %</translation>
    </message>
    <message>
        <source>override %1 %</source>
        <translation>corrección %1 %</translation>
    </message>
    <message>
        <source>classic law, %1 ms</source>
        <translation>ley clásica, %1 ms</translation>
    </message>
    <message>
        <source>engineered law, %1 ms</source>
        <translation>ley moderna, %1 ms</translation>
    </message>
    <message>
        <source>Cycle %1:%2</source>
        <translation>Ciclo %1:%2</translation>
    </message>
    <message>
        <source>Dwell %1 s</source>
        <translation>Espera %1 s</translation>
    </message>
    <message>
        <source>Block %1 / %2</source>
        <translation>Bloque %1 / %2</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ExecutionPanel</name>
    <message>
        <source>Alarms :</source>
        <translation>Alarmas :</translation>
    </message>
    <message>
        <source>Status :</source>
        <translation>Estado :</translation>
    </message>
    <message>
        <source>Automatic Mode :</source>
        <translation>Modo Automático :</translation>
    </message>
    <message>
        <source>Manual Mode :</source>
        <translation>Modo Manual :</translation>
    </message>
    <message>
        <source>Current Data :</source>
        <translation>Datos Actuales :</translation>
    </message>
    <message>
        <source>Controller :</source>
        <translation>Controlador :</translation>
    </message>
    <message>
        <source>Loop :</source>
        <translation>Lazo :</translation>
    </message>
    <message>
        <source>Program :</source>
        <translation>Programa :</translation>
    </message>
    <message>
        <source>Line :</source>
        <translation>Línea :</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continuar</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Izquierda</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Derecha</translation>
    </message>
    <message>
        <source>STOP</source>
        <translation>PARA</translation>
    </message>
    <message>
        <source>Position :</source>
        <translation>Posición :</translation>
    </message>
    <message>
        <source>Speed :</source>
        <translation>Velocidad :</translation>
    </message>
    <message>
        <source>Acceleration :</source>
        <translation>Aceleración :</translation>
    </message>
    <message>
        <source>Proportional :</source>
        <translation>Proporcional :</translation>
    </message>
    <message>
        <source>Derivative :</source>
        <translation>Derivativa :</translation>
    </message>
    <message>
        <source>Integral :</source>
        <translation>Integral :</translation>
    </message>
    <message>
        <source>Setpoint :</source>
        <translation>Consigna :</translation>
    </message>
    <message>
        <source>Actual value :</source>
        <translation>Valor real :</translation>
    </message>
    <message>
        <source>Error :</source>
        <translation>Error :</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>línea %1</translation>
    </message>
</context>
<context>
    <name>trilho::ui::GuideDialog</name>
    <message>
        <source>The guide is not installed here: %1 cannot be read.</source>
        <translation>La guía no está instalada aquí: no se puede leer %1.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::HistoryPanel</name>
    <message>
        <source>Export history</source>
        <translation>Exportar historial</translation>
    </message>
    <message>
        <source>alarm</source>
        <translation>alarma</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>aviso</translation>
    </message>
    <message>
        <source>acknowledged</source>
        <translation>reconocido</translation>
    </message>
    <message>
        <source>status</source>
        <translation>estado</translation>
    </message>
    <message>
        <source>hold</source>
        <translation>espera</translation>
    </message>
    <message>
        <source>resume</source>
        <translation>reanudación</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>detenido</translation>
    </message>
    <message>
        <source>mode</source>
        <translation>modo</translation>
    </message>
    <message>
        <source>run start</source>
        <translation>inicio</translation>
    </message>
    <message>
        <source>run end</source>
        <translation>fin</translation>
    </message>
    <message>
        <source>override</source>
        <translation>corrección</translation>
    </message>
    <message>
        <source>DNC write</source>
        <translation>Escritura DNC</translation>
    </message>
    <message>
        <source>start</source>
        <translation>inicio</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>fin</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Hora</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <source>Code</source>
        <translation>Código</translation>
    </message>
    <message>
        <source>Text</source>
        <translation>Texto</translation>
    </message>
    <message>
        <source>Acknowledge alarms</source>
        <translation>Reconocer alarmas</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportar CSV</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
    <message>
        <source>The alarms, warnings, holds, overrides, mode changes and DNC writes of the history on a time axis</source>
        <translation>Las alarmas, avisos, esperas, correcciones de avance, cambios de modo y escrituras DNC del historial en un eje de tiempo</translation>
    </message>
</context>
<context>
    <name>trilho::ui::JogPanel</name>
    <message>
        <source>Hold a key to jog</source>
        <translation>Mantenga una tecla para mover</translation>
    </message>
    <message>
        <source>Hold to jog toward -X</source>
        <translation>Mantenga para mover hacia -X</translation>
    </message>
    <message>
        <source>Hold to jog toward +X</source>
        <translation>Mantenga para mover hacia +X</translation>
    </message>
    <message>
        <source>Jog speed %1 mm/s</source>
        <translation>Velocidad manual %1 mm/s</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
</context>
<context>
    <name>trilho::ui::KeysDialog</name>
    <message>
        <source>EMERGENCY STOP, in every window, menu and dialog</source>
        <translation>PARADA DE EMERGENCIA, en cualquier ventana, menú o diálogo</translation>
    </message>
    <message>
        <source>Stop (a controlled stop) when no menu, list or dialog is open; otherwise it only closes it</source>
        <translation>Detener (parada controlada) cuando no hay menú, lista ni diálogo abierto; si lo hay, solo lo cierra</translation>
    </message>
    <message>
        <source>STOP: the manual PARA, or Stop in automatic (not in the editor)</source>
        <translation>PARA: el PARA manual, o Detener en automático (no en el editor)</translation>
    </message>
    <message>
        <source>Manual mode: left</source>
        <translation>Modo manual: izquierda</translation>
    </message>
    <message>
        <source>Manual mode: right</source>
        <translation>Modo manual: derecha</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>Teclas</translation>
    </message>
    <message>
        <source>Key</source>
        <translation>Tecla</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Acción</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MachineChoice</name>
    <message>
        <source>DC-motor XY table</source>
        <translation>Mesa XY con motores CC</translation>
    </message>
    <message>
        <source>Stepper XY plotter</source>
        <translation>Plotter XY con motores paso a paso</translation>
    </message>
    <message>
        <source>Robot rail (1996)</source>
        <translation>Riel del robot (1996)</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>&amp;Machine:</source>
        <translation>&amp;Máquina:</translation>
    </message>
    <message>
        <source>%1 is moving. Switching to %2 stops it first (a controlled stop) and closes its screen. Switch?</source>
        <translation>%1 está en movimiento. Cambiar a %2 lo detiene antes (parada controlada) y cierra su pantalla. ¿Cambiar?</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MachineLink</name>
    <message>
        <source>The simulated rail started again at x = 0 mm: the run that was going is lost; Execute homes it first.</source>
        <translation>El riel simulado volvió a empezar en x = 0 mm: la ejecución en curso se perdió; Ejecutar lo referencia antes.</translation>
    </message>
    <message>
        <source>Command not taken: the servo thread&apos;s queue is full. Press again.</source>
        <translation>Comando no aceptado: la cola del servo está llena. Pulse de nuevo.</translation>
    </message>
    <message>
        <source>Program not started: the servo thread is still taking the one before it, or its queue is full. Press again.</source>
        <translation>Programa no iniciado: el servo todavía está recibiendo el anterior, o su cola está llena. Pulse de nuevo.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MainWindow</name>
    <message>
        <source>Start from a block runs in Automatic: choose Command &gt; Automatic first (it homes the rail).</source>
        <translation>Iniciar desde un bloque funciona en Automático: elija antes Comando &gt; Automático (referencia el riel).</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>línea %1</translation>
    </message>
    <message>
        <source>Start from the selected block</source>
        <translation>Ejecutar desde el bloque seleccionado</translation>
    </message>
    <message>
        <source>Start %1 from block %2? %3%4</source>
        <translation>¿Iniciar %1 desde el bloque %2? %3%4</translation>
    </message>
    <message>
        <source>Its position is not known, so it homes first: %1 </source>
        <translation>La posición no se conoce, así que primero hace la referencia: %1 </translation>
    </message>
    <message>
        <source>Didactic D.N.C. system for the automatic rail</source>
        <translation>Sistema D.N.C. didáctico para riel automático</translation>
    </message>
    <message>
        <source>&amp;Select</source>
        <translation>&amp;Seleccionar</translation>
    </message>
    <message>
        <source>&amp;Compile file</source>
        <translation>&amp;Compilar archivo</translation>
    </message>
    <message>
        <source>&amp;Execute file</source>
        <translation>&amp;Ejecutar archivo</translation>
    </message>
    <message>
        <source>&amp;Theme</source>
        <translation>&amp;Tema</translation>
    </message>
    <message>
        <source>Classic (1996 colours)</source>
        <translation>Clásico (colores de 1996)</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Sistema</translation>
    </message>
    <message>
        <source>Control &amp;law</source>
        <translation>&amp;Ley de control</translation>
    </message>
    <message>
        <source>Classic (the 1996 difference equation)</source>
        <translation>Clásica (la ecuación en diferencias de 1996)</translation>
    </message>
    <message>
        <source>Engineered (profile, feed-forward)</source>
        <translation>Diseñada (perfil, prealimentación)</translation>
    </message>
    <message>
        <source>G-code &amp;dialect</source>
        <translation>&amp;Dialecto de código G</translation>
    </message>
    <message>
        <source>Standard</source>
        <translation>Estándar</translation>
    </message>
    <message>
        <source>Classic (1996)</source>
        <translation>Clásico (1996)</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Rail</source>
        <translation>Riel</translation>
    </message>
    <message>
        <source>EMERGENCY STOP LATCHED: the drive is off. Clear the cause, then Reset E-stop.</source>
        <translation>PARADA DE EMERGENCIA ENCLAVADA: el accionamiento está apagado. Elimine la causa y luego Liberar emergencia.</translation>
    </message>
    <message>
        <source>Set in the Simulation dock; Clear all there puts the rail right.</source>
        <translation>Definida en el panel Simulación; Borrar todo allí corrige el riel.</translation>
    </message>
    <message>
        <source>File message</source>
        <translation>Mensaje de archivo</translation>
    </message>
    <message>
        <source>Select the file first !</source>
        <translation>¡Seleccione el archivo primero!</translation>
    </message>
    <message>
        <source>The program is loading: it compiles when it is loaded.</source>
        <translation>El programa se está cargando: se compilará cuando esté cargado.</translation>
    </message>
    <message>
        <source>%1 changed on disk: reading it again.</source>
        <translation>%1 cambió en el disco: leyéndolo de nuevo.</translation>
    </message>
    <message>
        <source>The program changed while it compiled: nothing was run. Compile or execute it again.</source>
        <translation>El programa cambió mientras se compilaba: no se ejecutó nada. Compílelo o ejecútelo de nuevo.</translation>
    </message>
    <message>
        <source>Compiling %1 MB...</source>
        <translation>Compilando %1 MB...</translation>
    </message>
    <message>
        <source>End</source>
        <translation>Final</translation>
    </message>
    <message>
        <source>Compilation finished !</source>
        <translation>¡Compilación terminada!</translation>
    </message>
    <message>
        <source>Execute %1? %2%3 Then it runs the program.</source>
        <translation>¿Ejecutar %1? %2%3 Luego ejecuta el programa.</translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation>Inicio de ciclo</translation>
    </message>
    <message>
        <source> (the rail centre, where every program starts, as in the 1996 program)</source>
        <translation> (el centro del riel, donde empieza todo programa, como en el programa de 1996)</translation>
    </message>
    <message>
        <source> (first programmed move to x = %1 mm)</source>
        <translation> (primer movimiento programado a x = %1 mm)</translation>
    </message>
    <message>
        <source>It starts where homing leaves it, at x = %1 mm%2%3.</source>
        <translation>Empieza donde lo deja la referencia, en x = %1 mm%2%3.</translation>
    </message>
    <message>
        <source>It starts where it stands, at x = %1 mm%2%3.</source>
        <translation>Empieza donde está, en x = %1 mm%2%3.</translation>
    </message>
    <message>
        <source>The rail moves at rapid speed from x = %1 mm to x = %2 mm%3%4.</source>
        <translation>El riel se mueve a velocidad rápida de x = %1 mm a x = %2 mm%3%4.</translation>
    </message>
    <message>
        <source>the rail drives right until a switch: the centre mark if it is left of the centre; otherwise the right end switch (about x = +%1 mm), then back left to the centre mark</source>
        <translation>el riel avanza a la derecha hasta un interruptor: la marca central si está a la izquierda del centro; si no, el final de carrera derecho (cerca de x = +%1 mm), y vuelve a la izquierda hasta la marca central</translation>
    </message>
    <message>
        <source>the rail drives right from x = %1 mm to the centre mark</source>
        <translation>el riel avanza a la derecha de x = %1 mm hasta la marca central</translation>
    </message>
    <message>
        <source>the rail drives right from x = %1 mm to the right end switch (about x = +%2 mm), then back left to the centre mark</source>
        <translation>el riel avanza a la derecha de x = %1 mm hasta el final de carrera derecho (cerca de x = +%2 mm), y vuelve a la izquierda hasta la marca central</translation>
    </message>
    <message>
        <source>%1, and stops at x = 0.</source>
        <translation>%1, y se detiene en x = 0.</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automático</translation>
    </message>
    <message>
        <source>Automatic homes the rail first, as in 1996: %1 Home now?</source>
        <translation>El modo automático primero referencia el riel, como en 1996: %1 ¿Referenciar ahora?</translation>
    </message>
    <message>
        <source>Home: stop the rail (or reset the E-stop, acknowledge the alarm) first.</source>
        <translation>Referenciar: detenga el riel (o rearme la emergencia, reconozca la alarma) antes.</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Referenciar</translation>
    </message>
    <message>
        <source>Home the rail? %1%2</source>
        <translation>¿Referenciar el riel? %1%2</translation>
    </message>
    <message>
        <source> It then stays in Automatic.</source>
        <translation> Después queda en Automático.</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <source>There are compile error(s)!</source>
        <translation>¡Hay error(es) de compilación!</translation>
    </message>
    <message>
        <source>Late ticks: %1 (longest %2 ms)</source>
        <translation>Ciclos atrasados: %1 (mayor %2 ms)</translation>
    </message>
    <message>
        <source>%1 status lines not shown</source>
        <translation>%1 líneas de estado no mostradas</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Automatic, ready</source>
        <translation>Automático, listo</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Referenciando</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Ejecutando</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>Esperando</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pausado</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarma</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Parada de emergencia</translation>
    </message>
    <message>
        <source>The history could not be written: %1</source>
        <translation>No se pudo escribir el historial: %1</translation>
    </message>
    <message>
        <source>Emergency stop: clear the cause, then Reset E-stop.</source>
        <translation>Parada de emergencia: elimine la causa y luego pulse Liberar emergencia.</translation>
    </message>
    <message>
        <source>Alarm: read it in Alarms, then Acknowledge. Execute then homes the rail first if its position was lost.</source>
        <translation>Alarma: léala en Alarmas y Reconozca. Ejecutar entonces referencia el riel primero si se perdió la posición.</translation>
    </message>
    <message>
        <source>Alarm: read it in Alarms, then Acknowledge.</source>
        <translation>Alarma: léala en Alarmas y Reconozca.</translation>
    </message>
    <message>
        <source>The rail&apos;s position is not known: Execute (or Automatic) homes it first.</source>
        <translation>La posición del riel no se conoce: Ejecutar (o Automático) la referencia primero.</translation>
    </message>
    <message>
        <source>Held: Resume goes on, Stop ends the program.</source>
        <translation>Retenido: Reanudar continúa, Parar termina el programa.</translation>
    </message>
    <message>
        <source>Cycle start runs in Automatic: choose Command &gt; Automatic first (it homes the rail).</source>
        <translation>El inicio de ciclo funciona en Automático: elija antes Comando &gt; Automático (referencia el riel).</translation>
    </message>
    <message>
        <source>Unsaved program</source>
        <translation>Programa sin guardar</translation>
    </message>
    <message>
        <source>The program has unsaved changes. Save them before leaving?</source>
        <translation>El programa tiene cambios sin guardar. ¿Guardarlos antes de salir?</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Exit</source>
        <translation>Salir</translation>
    </message>
    <message>
        <source>The rail is moving (x = %1 mm, towards x = %2 mm). Exit stops it with an emergency stop. Exit now?</source>
        <translation>El carril se está moviendo (x = %1 mm, hacia x = %2 mm). Salir lo detiene con una parada de emergencia. ¿Salir ahora?</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MarginView</name>
    <message>
        <source>%1: no lost step up to %2 %3; the profile&apos;s %4 %3 has a margin of %5 (%6 %)</source>
        <translation>%1: ningún paso perdido hasta %2 %3; los %4 %3 del perfil tienen un margen de %5 (%6 %)</translation>
    </message>
    <message>
        <source>%1: no lost step in the whole sweep (or as far as the travel lets a move reach its speed), up to %2 %3 (margin at least %4)</source>
        <translation>%1: ningún paso perdido en todo el barrido (o hasta donde el recorrido deja que un movimiento alcance su velocidad), hasta %2 %3 (margen de al menos %4)</translation>
    </message>
    <message>
        <source>Margin test refused: %1</source>
        <translation>Prueba de margen rechazada: %1</translation>
    </message>
    <message>
        <source>Axis %1: %2 trials out and back, %3 s of machine time (simulation only: the board reports no step count; on the machine, check a pen mark at the start).</source>
        <translation>Eje %1: %2 ensayos de ida y vuelta, %3 s de tiempo de máquina (solo simulación: la placa no informa la cuenta de pasos; en la máquina, compruebe una marca de lápiz en el inicio).</translation>
    </message>
    <message>
        <source>Speed at the profile&apos;s acceleration</source>
        <translation>Velocidad con la aceleración del perfil</translation>
    </message>
    <message>
        <source>Acceleration at the profile&apos;s speed</source>
        <translation>Aceleración a la velocidad del perfil</translation>
    </message>
    <message>
        <source>no loss</source>
        <translation>sin pérdida</translation>
    </message>
    <message>
        <source>lost steps</source>
        <translation>pasos perdidos</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>aceleración</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Barrido</translation>
    </message>
    <message>
        <source>Speed (mm/s)</source>
        <translation>Velocidad (mm/s)</translation>
    </message>
    <message>
        <source>Acceleration (mm/s²)</source>
        <translation>Aceleración (mm/s²)</translation>
    </message>
    <message>
        <source>Move (mm)</source>
        <translation>Movimiento (mm)</translation>
    </message>
    <message>
        <source>Lost steps</source>
        <translation>Pasos perdidos</translation>
    </message>
    <message>
        <source>Return error (steps)</source>
        <translation>Error al volver (pasos)</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Resultado</translation>
    </message>
    <message>
        <source>The plotter has no encoder: its test is the margin of its speed and acceleration against lost steps. Choose the axis and press Run margin test.</source>
        <translation>El plotter no tiene encoder: su prueba es el margen de su velocidad y aceleración frente a pasos perdidos. Elija el eje y pulse Ejecutar prueba de margen.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ModelView</name>
    <message>
        <source>Identify or autotune the rail to see its model, its fit and its Bode plot.</source>
        <translation>Identifique el riel o haga el autoajuste para ver su modelo, su ajuste y su diagrama de Bode.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Identified model&lt;/b&gt; (G = K / (s (tau s + 1)), acceleration limited, Coulomb friction)</source>
        <translation>&lt;b&gt;Modelo identificado&lt;/b&gt; (G = K / (s (tau s + 1)), aceleración limitada, fricción de Coulomb)</translation>
    </message>
    <message>
        <source>speed gain K = %1 mm/s per code</source>
        <translation>ganancia de velocidad K = %1 mm/s por código</translation>
    </message>
    <message>
        <source>time constant tau = %1 ms</source>
        <translation>constante de tiempo tau = %1 ms</translation>
    </message>
    <message>
        <source>acceleration limit = %1 mm/s2 (mass %2 kg)</source>
        <translation>límite de aceleración = %1 mm/s2 (masa %2 kg)</translation>
    </message>
    <message>
        <source>Coulomb friction = %1 mm/s2 (%2 N)</source>
        <translation>fricción de Coulomb = %1 mm/s2 (%2 N)</translation>
    </message>
    <message>
        <source>fit on held-out velocity (NRMSE) = &lt;b&gt;%1 %&lt;/b&gt;; on the fitted part %2 %; on position %3 % (flattering: position integrates)</source>
        <translation>ajuste en la velocidad de validación (NRMSE) = &lt;b&gt;%1 %&lt;/b&gt;; en la parte ajustada %2 %; en la posición %3 % (optimista: la posición integra)</translation>
    </message>
    <message>
        <source>experiment: %1 s of machine time, at most %2 mm from the start, back within %3 counts</source>
        <translation>experimento: %1 s de tiempo de máquina, como máximo a %2 mm del inicio, de vuelta a menos de %3 cuentas</translation>
    </message>
    <message>
        <source>Model refused: %1</source>
        <translation>Modelo rechazado: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Margins&lt;/b&gt;: gain %1 dB at %2 rad/s; phase %3 deg at %4 rad/s</source>
        <translation>&lt;b&gt;Márgenes&lt;/b&gt;: ganancia %1 dB a %2 rad/s; fase %3 deg a %4 rad/s</translation>
    </message>
    <message>
        <source>infinite</source>
        <translation>infinita</translation>
    </message>
    <message>
        <source>|L| (dB)</source>
        <translation>|L| (dB)</translation>
    </message>
    <message>
        <source>phase (deg)</source>
        <translation>fase (deg)</translation>
    </message>
    <message>
        <source>frequency (rad/s)</source>
        <translation>frecuencia (rad/s)</translation>
    </message>
    <message>
        <source>Open loop with the profile&apos;s engineered gains (Kp %1, Ki %2, Kd %3):</source>
        <translation>Lazo abierto con las ganancias de la ley moderna del perfil (Kp %1, Ki %2, Kd %3):</translation>
    </message>
    <message>
        <source>&lt;b&gt;Design&lt;/b&gt; (SIMC, closed-loop time constant %1 ms, delay %2 ms): Kp %3, Ki %4, Kd %5; planning acceleration %6 mm/s2</source>
        <translation>&lt;b&gt;Diseño&lt;/b&gt; (SIMC, constante de tiempo en lazo cerrado %1 ms, retardo %2 ms): Kp %3, Ki %4, Kd %5; aceleración de planificación %6 mm/s2</translation>
    </message>
    <message>
        <source>Prediction (on the model, before applying) against measurement</source>
        <translation>Predicción (en el modelo, antes de aplicar) frente a medición</translation>
    </message>
    <message>
        <source>overshoot predicted (counts)</source>
        <translation>sobreimpulso previsto (cuentas)</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message>
        <source>settling +-1 count predicted (ms)</source>
        <translation>establecimiento +-1 cuenta previsto (ms)</translation>
    </message>
    <message>
        <source>%1 mm step</source>
        <translation>escalón de %1 mm</translation>
    </message>
    <message>
        <source>%1 mm move</source>
        <translation>movimiento de %1 mm</translation>
    </message>
    <message>
        <source>Machine time of the whole autotune: %1 s</source>
        <translation>Tiempo de máquina de todo el autoajuste: %1 s</translation>
    </message>
    <message>
        <source>&lt;b&gt;Autotune passed&lt;/b&gt;: the tuned gains are in the step test&apos;s boxes; Save tuned profile... keeps them in a profile.</source>
        <translation>&lt;b&gt;Autoajuste aprobado&lt;/b&gt;: las ganancias sintonizadas están en las casillas de la prueba de escalón; Guardar perfil sintonizado... las guarda en un perfil.</translation>
    </message>
    <message>
        <source>Autotune failed: %1</source>
        <translation>Autoajuste fallido: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Identified model&lt;/b&gt; (PWM-driven motor: G = K / (s (tau s + 1)), Coulomb friction)</source>
        <translation>&lt;b&gt;Modelo identificado&lt;/b&gt; (motor accionado por PWM: G = K / (s (tau s + 1)), fricción de Coulomb)</translation>
    </message>
    <message>
        <source>speed gain K = %1 mm/s per PWM %</source>
        <translation>ganancia de velocidad K = %1 mm/s por % de PWM</translation>
    </message>
    <message>
        <source>time constant tau = %1 ms (inertia x%2 of the profile&apos;s)</source>
        <translation>constante de tiempo tau = %1 ms (inercia x%2 de la del perfil)</translation>
    </message>
    <message>
        <source>Coulomb friction = %1 % PWM</source>
        <translation>fricción de Coulomb = %1 % de PWM</translation>
    </message>
    <message>
        <source>acceleration limit = %1 mm/s2 (the over-current trip)</source>
        <translation>límite de aceleración = %1 mm/s2 (el disparo de sobrecorriente)</translation>
    </message>
    <message>
        <source>Open loop with the profile&apos;s engineered gains (Kp %1, Ki %2, Kff %3):</source>
        <translation>Lazo abierto con las ganancias de la ley de ingeniería del perfil (Kp %1, Ki %2, Kff %3):</translation>
    </message>
    <message>
        <source>&lt;b&gt;Design&lt;/b&gt; (SIMC PI, closed-loop time constant %1 ms, effective delay %2 ms): Kp %3, Ki %4, Kff %5; planning acceleration %6 mm/s2</source>
        <translation>&lt;b&gt;Diseño&lt;/b&gt; (PI SIMC, constante de tiempo en lazo cerrado %1 ms, retardo efectivo %2 ms): Kp %3, Ki %4, Kff %5; aceleración de planificación %6 mm/s2</translation>
    </message>
    <message>
        <source>&lt;b&gt;Relay experiment&lt;/b&gt; (Astrom-Hagglund): a relay of +-%1 codes on the position error, hysteresis %2 counts</source>
        <translation>&lt;b&gt;Experimento del relé&lt;/b&gt; (Astrom-Hagglund): un relé de +-%1 códigos sobre el error de posición, histéresis de %2 cuentas</translation>
    </message>
    <message>
        <source>limit cycle: amplitude a = %1 mm, period Tu = %2 ms</source>
        <translation>ciclo límite: amplitud a = %1 mm, período Tu = %2 ms</translation>
    </message>
    <message>
        <source>ultimate gain Ku = 4 d / (pi a) = %1 code/mm</source>
        <translation>ganancia crítica Ku = 4 d / (pi a) = %1 código/mm</translation>
    </message>
    <message>
        <source>Relay experiment failed: %1</source>
        <translation>El experimento del relé falló: %1</translation>
    </message>
    <message>
        <source>experiment: %1 s of machine time, back within %2 counts</source>
        <translation>experimento: %1 s de tiempo de máquina, de vuelta a %2 cuentas</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>no alcanzado</translation>
    </message>
    <message>
        <source>Ziegler-Nichols (relay)</source>
        <translation>Ziegler-Nichols (relé)</translation>
    </message>
    <message>
        <source>model-based (SIMC)</source>
        <translation>basado en el modelo (SIMC)</translation>
    </message>
    <message>
        <source>Kp (code/mm)</source>
        <translation>Kp (código/mm)</translation>
    </message>
    <message>
        <source>Ki (code/(mm.s))</source>
        <translation>Ki (código/(mm.s))</translation>
    </message>
    <message>
        <source>Kd (code/(mm/s))</source>
        <translation>Kd (código/(mm/s))</translation>
    </message>
    <message>
        <source>10 mm step: overshoot (%)</source>
        <translation>escalón de 10 mm: sobreimpulso (%)</translation>
    </message>
    <message>
        <source>rise time 10-90 % (s)</source>
        <translation>tiempo de subida 10-90 % (s)</translation>
    </message>
    <message>
        <source>settling to +-1 count (s)</source>
        <translation>establecimiento a +-1 cuenta (s)</translation>
    </message>
    <message>
        <source>steady-state error (counts)</source>
        <translation>error en régimen (cuentas)</translation>
    </message>
    <message>
        <source>no</source>
        <translation>No</translation>
    </message>
    <message>
        <source>aborted: %1</source>
        <translation>abortado: %1</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>abortado</translation>
    </message>
    <message>
        <source>An experiment to teach with, not the default tuning: on this plant the DAC&apos;s quantization, the friction and the current limit set the limit cycle as much as the dynamics do.</source>
        <translation>Un experimento para enseñar, no la sintonía por defecto: en esta planta la cuantización del DAC, la fricción y el límite de corriente fijan el ciclo límite tanto como la dinámica.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::OperatorFrame</name>
    <message>
        <source>Operator&apos;s guide</source>
        <translation>Guía del operador</translation>
    </message>
    <message>
        <source>Teaching guide</source>
        <translation>Guía de enseñanza</translation>
    </message>
    <message>
        <source>About trilho</source>
        <translation>Acerca de trilho</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;trilho %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Numerical control for the robot rail of the 1996 manufacturing cell (University of São Paulo) and two XY tables, simulated by default.&lt;/p&gt;&lt;p&gt;Guides: %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;trilho %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Control numérico para el riel del robot de la celda de manufactura de 1996 (Universidad de São Paulo) y dos mesas XY, simuladas por defecto.&lt;/p&gt;&lt;p&gt;Guías: %2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Settings not saved: cannot write %1 (a full disk or a folder that cannot be written). The old settings are kept; this change holds until trilho closes.</source>
        <translation>Configuración no guardada: no se puede escribir %1 (disco lleno o carpeta sin permiso de escritura). Se conserva la configuración anterior; este cambio vale hasta que trilho se cierre.</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Machine...</source>
        <translation>&amp;Máquina...</translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation>Sa&amp;lir</translation>
    </message>
    <message>
        <source>C&amp;ommand</source>
        <translation>C&amp;omando</translation>
    </message>
    <message>
        <source>&amp;Manual</source>
        <translation>&amp;Manual</translation>
    </message>
    <message>
        <source>&amp;Automatic</source>
        <translation>&amp;Automático</translation>
    </message>
    <message>
        <source>&amp;Home</source>
        <translation>&amp;Referenciar</translation>
    </message>
    <message>
        <source>Home (Ctrl+Home)</source>
        <translation>Referenciar (Ctrl+Inicio)</translation>
    </message>
    <message>
        <source>O&amp;ptions</source>
        <translation>O&amp;pciones</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>&amp;DNC link...</source>
        <translation>Enlace &amp;DNC...</translation>
    </message>
    <message>
        <source>&amp;Remote (DNC)</source>
        <translation>&amp;Remoto (DNC)</translation>
    </message>
    <message>
        <source>Allow the cell&apos;s supervisor to write and command over the DNC link (%1). Off at every start.</source>
        <translation>Permite al supervisor de la célula escribir y mandar por el enlace DNC (%1). Desactivado en cada inicio.</translation>
    </message>
    <message>
        <source>&amp;Windows</source>
        <translation>&amp;Ventanas</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Restablecer disposición</translation>
    </message>
    <message>
        <source>Tuning &amp;workbench...</source>
        <translation>&amp;Banco de sintonía...</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation>&amp;Teclas</translation>
    </message>
    <message>
        <source>&amp;Operator&apos;s guide</source>
        <translation>Guía del &amp;operador</translation>
    </message>
    <message>
        <source>&amp;Teaching guide</source>
        <translation>Guía de &amp;enseñanza</translation>
    </message>
    <message>
        <source>&amp;About trilho</source>
        <translation>&amp;Acerca de trilho</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Historial</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulación</translation>
    </message>
    <message>
        <source>Program library</source>
        <translation>Biblioteca</translation>
    </message>
    <message>
        <source>Safety</source>
        <translation>Seguridad</translation>
    </message>
    <message>
        <source>Reset E-stop</source>
        <translation>Liberar emergencia</translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation>Reconocer</translation>
    </message>
    <message>
        <source>E-STOP LATCHED</source>
        <translation>EMERGENCIA ACTIVADA</translation>
    </message>
    <message>
        <source>E-STOP (Pause, F1)</source>
        <translation>EMERGENCIA (Pausa, F1)</translation>
    </message>
    <message>
        <source>Simulated fault armed: %1</source>
        <translation>Falla simulada activa: %1</translation>
    </message>
    <message>
        <source>Feed override %1 %</source>
        <translation>Corrección de avance %1 %</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PlotPanel</name>
    <message>
        <source>Export PNG</source>
        <translation>Exportar PNG</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportar CSV</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausar</translation>
    </message>
    <message>
        <source>Rolling window</source>
        <translation>Ventana de tiempo</translation>
    </message>
    <message>
        <source>setpoint</source>
        <translation>consigna</translation>
    </message>
    <message>
        <source>position</source>
        <translation>posición</translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation>posición (mm)</translation>
    </message>
    <message>
        <source>error (mm)</source>
        <translation>error (mm)</translation>
    </message>
    <message>
        <source>DAC</source>
        <translation>DAC</translation>
    </message>
    <message>
        <source>following error (mm)</source>
        <translation>error de seguimiento (mm)</translation>
    </message>
    <message>
        <source>drive (DAC code)</source>
        <translation>accionamiento (código DAC)</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: the image could not be encoded</source>
        <translation>no se puede escribir &apos;%1&apos;: la imagen no se pudo codificar</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PlotterCommLog</name>
    <message>
        <source>Sending object %1</source>
        <translation>Enviando objeto %1</translation>
    </message>
    <message>
        <source>Sending: %1</source>
        <translation>Enviando: %1</translation>
    </message>
    <message>
        <source>Received: %1</source>
        <translation>Recibido: %1</translation>
    </message>
    <message>
        <source>Time: %1 s</source>
        <translation>Tiempo: %1 s</translation>
    </message>
    <message>
        <source>Communication log</source>
        <translation>Registro de comunicación</translation>
    </message>
    <message>
        <source>Clear log</source>
        <translation>Limpiar registro</translation>
    </message>
    <message>
        <source>No object sent yet</source>
        <translation>Ningún objeto enviado todavía</translation>
    </message>
    <message>
        <source>Last object: %1 s</source>
        <translation>Último objeto: %1 s</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PlotterPanel</name>
    <message>
        <source>Plotter</source>
        <translation>Plotter</translation>
    </message>
    <message>
        <source>Origin</source>
        <translation>Origen</translation>
    </message>
    <message>
        <source>Jog up (+y)</source>
        <translation>Mover hacia arriba (+y)</translation>
    </message>
    <message>
        <source>Jog down (-y)</source>
        <translation>Mover hacia abajo (-y)</translation>
    </message>
    <message>
        <source>Jog left (-x)</source>
        <translation>Mover a la izquierda (-x)</translation>
    </message>
    <message>
        <source>Jog right (+x)</source>
        <translation>Mover a la derecha (+x)</translation>
    </message>
    <message>
        <source>Jog step</source>
        <translation>Paso del movimiento</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source> steps/s</source>
        <translation> pasos/s</translation>
    </message>
    <message>
        <source>Object: %1 points (at most 300 per object)</source>
        <translation>Objeto: %1 puntos (como máximo 300 por objeto)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PolesView</name>
    <message>
        <source>Seed 004&apos;s law as written has no poles: it drives by |e| with the move&apos;s direction bit fixed, not a linear loop (past the target it drives on). Its signed reading, with the same b0 and b1, has them.</source>
        <translation>La ley del seed 004 tal como escrita no tiene polos: acciona por |e| con el bit de dirección del movimiento fijo, no es un lazo lineal (pasado el objetivo, sigue accionando). Su lectura con signo, con los mismos b0 y b1, los tiene.</translation>
    </message>
    <message>
        <source>Identify the plant to see the closed loop&apos;s poles and zeros for the gains in the boxes.</source>
        <translation>Identifique la planta para ver los polos y ceros del lazo cerrado con las ganancias de las casillas.</translation>
    </message>
    <message>
        <source>engineered</source>
        <translation>moderna</translation>
    </message>
    <message>
        <source>seed 004 (signed error)</source>
        <translation>seed 004 (error con signo)</translation>
    </message>
    <message>
        <source>1996</source>
        <translation>1996</translation>
    </message>
    <message>
        <source>&lt;b&gt;Closed loop at T = %1 ms&lt;/b&gt; (%2 law, %3; model K %4 %5, tau %6 ms)</source>
        <translation>&lt;b&gt;Lazo cerrado a T = %1 ms&lt;/b&gt; (ley %2, %3; modelo K %4 %5, tau %6 ms)</translation>
    </message>
    <message>
        <source>mm/s per PWM %</source>
        <translation>mm/s por % de PWM</translation>
    </message>
    <message>
        <source>mm/s per code</source>
        <translation>mm/s por código</translation>
    </message>
    <message>
        <source>poles (x):</source>
        <translation>polos (x):</translation>
    </message>
    <message>
        <source>%1 (|z| %2)</source>
        <translation>%1 (|z| %2)</translation>
    </message>
    <message>
        <source>zeros (o):</source>
        <translation>ceros (o):</translation>
    </message>
    <message>
        <source>largest |z| %1: stable, inside the unit circle.</source>
        <translation>mayor |z| %1: estable, dentro del círculo unitario.</translation>
    </message>
    <message>
        <source>&lt;font color=&quot;#c00000&quot;&gt;&lt;b&gt;largest |z| %1: unstable, on or outside the unit circle.&lt;/b&gt;&lt;/font&gt;</source>
        <translation>&lt;font color=&quot;#c00000&quot;&gt;&lt;b&gt;mayor |z| %1: inestable, sobre o fuera del círculo unitario.&lt;/b&gt;&lt;/font&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dominant pair&lt;/b&gt; %1: damping %2, natural frequency %3 rad/s (z = exp(sT), s = ln z / T)</source>
        <translation>&lt;b&gt;Par dominante&lt;/b&gt; %1: amortiguamiento %2, frecuencia natural %3 rad/s (z = exp(sT), s = ln z / T)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dominant pole&lt;/b&gt; %1: damping %2, natural frequency %3 rad/s (z = exp(sT), s = ln z / T)</source>
        <translation>&lt;b&gt;Polo dominante&lt;/b&gt; %1: amortiguamiento %2, frecuencia natural %3 rad/s (z = exp(sT), s = ln z / T)</translation>
    </message>
    <message>
        <source>The loop leaves the unit circle above %1 %2.</source>
        <translation>El lazo sale del círculo unitario por encima de %1 %2.</translation>
    </message>
    <message>
        <source>... and below %1 %2.</source>
        <translation>... y por debajo de %1 %2.</translation>
    </message>
    <message>
        <source>Root locus (grey): %1 from %2 to %3; the poles for the gains in the boxes are the crosses.</source>
        <translation>Lugar de las raíces (gris): %1 de %2 a %3; los polos de las ganancias de las casillas son las cruces.</translation>
    </message>
    <message>
        <source>unit circle</source>
        <translation>círculo unitario</translation>
    </message>
    <message>
        <source>root locus (Kp)</source>
        <translation>lugar de las raíces (Kp)</translation>
    </message>
    <message>
        <source>zeros</source>
        <translation>ceros</translation>
    </message>
    <message>
        <source>poles</source>
        <translation>polos</translation>
    </message>
    <message>
        <source>Re z</source>
        <translation>Re z</translation>
    </message>
    <message>
        <source>Im z</source>
        <translation>Im z</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PolygonDialog</name>
    <message>
        <source>line %1: expected two numbers, x and y in mm (got &apos;%2&apos;)</source>
        <translation>línea %1: se esperaban dos números, x e y en mm (llegó &apos;%2&apos;)</translation>
    </message>
    <message>
        <source>a polygon needs at least three points (got %1)</source>
        <translation>un polígono necesita al menos tres puntos (llegaron %1)</translation>
    </message>
    <message>
        <source>Polygon from points</source>
        <translation>Polígono por puntos</translation>
    </message>
    <message>
        <source>One point a line: x y in mm (e.g. 20 20)</source>
        <translation>Un punto por línea: x y en mm (p. ej. 20 20)</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>Plotear</translation>
    </message>
    <message>
        <source>Vertices (x y, mm):</source>
        <translation>Vértices (x y, mm):</translation>
    </message>
    <message>
        <source>Feed:</source>
        <translation>Avance:</translation>
    </message>
    <message>
        <source>The polygon is closed back to its first point.</source>
        <translation>El polígono se cierra volviendo al primer punto.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PredictionView</name>
    <message>
        <source>Seed 004&apos;s law as written is not a linear loop (|e| with the move&apos;s direction bit): no prediction. Run its step instead.</source>
        <translation>La ley del seed 004 tal como está escrita no es un lazo lineal (|e| con el bit de dirección del movimiento): no hay predicción. Ejecute su escalón.</translation>
    </message>
    <message>
        <source>Identify the plant to see the step the model predicts for the gains in the boxes; drag a gain&apos;s slider to move it.</source>
        <translation>Identifique la planta para ver el escalón que el modelo predice para las ganancias de las casillas; arrastre el control deslizante de una ganancia para moverlo.</translation>
    </message>
    <message>
        <source>No prediction: the period or the model is not valid.</source>
        <translation>Sin predicción: el período o el modelo no es válido.</translation>
    </message>
    <message>
        <source>Step of %1 mm predicted on the model (linear: no clamp, no feed-forward):</source>
        <translation>Escalón de %1 mm predicho en el modelo (lineal: sin limitación, sin feed-forward):</translation>
    </message>
    <message>
        <source>the loop is unstable, the response grows.</source>
        <translation>el lazo es inestable, la respuesta crece.</translation>
    </message>
    <message>
        <source>overshoot %1 %, not settled within %2 s.</source>
        <translation>sobreimpulso %1 %, no establecido en %2 s.</translation>
    </message>
    <message>
        <source>overshoot %1 %, settling (2 %) %2 s.</source>
        <translation>sobreimpulso %1 %, establecimiento (2 %) %2 s.</translation>
    </message>
    <message>
        <source>Grey: where the drag started.</source>
        <translation>Gris: donde empezó el arrastre.</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation>posición (mm)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ProgramLibraryPanel</name>
    <message>
        <source>Folder: %1</source>
        <translation>Carpeta: %1</translation>
    </message>
    <message>
        <source>Folder: %1 (not created yet)</source>
        <translation>Carpeta: %1 (aún no creada)</translation>
    </message>
    <message>
        <source>%1 bytes, no comment</source>
        <translation>%1 bytes, sin comentario</translation>
    </message>
    <message>
        <source>Not served: %1</source>
        <translation>No servido: %1</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>N.º</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Archivo</translation>
    </message>
    <message>
        <source>Comment or size</source>
        <translation>Comentario o tamaño</translation>
    </message>
    <message>
        <source>Modified</source>
        <translation>Modificado</translation>
    </message>
    <message>
        <source>Open in the editor</source>
        <translation>Abrir en el editor</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ProgramPanel</name>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Start from the selected block</source>
        <translation>Ejecutar desde el bloque seleccionado</translation>
    </message>
    <message>
        <source>A program this large is shown read-only: edit it in a text editor</source>
        <translation>Un programa de este tamaño se muestra solo para lectura: edítelo en un editor de texto</translation>
    </message>
    <message>
        <source>Saves atomically: a crash never leaves half a file</source>
        <translation>Guarda de forma atómica: un fallo nunca deja medio archivo</translation>
    </message>
    <message>
        <source>%1 lines: too large to edit here, shown read-only. Click a line to select its block.</source>
        <translation>%1 líneas: demasiado grande para editar aquí, se muestra solo para lectura. Haga clic en una línea para seleccionar su bloque.</translation>
    </message>
    <message>
        <source>Loading %1 (%2 MB)...</source>
        <translation>Cargando %1 (%2 MB)...</translation>
    </message>
    <message>
        <source>No program is selected: there is no file to save to.</source>
        <translation>Ningún programa seleccionado: no hay archivo donde guardar.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::RailView</name>
    <message>
        <source>left end</source>
        <translation>fin izquierdo</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>centro</translation>
    </message>
    <message>
        <source>right end</source>
        <translation>fin derecho</translation>
    </message>
</context>
<context>
    <name>trilho::ui::RunControls</name>
    <message>
        <source>Cycle start</source>
        <translation>Inicio de ciclo</translation>
    </message>
    <message>
        <source>Feed hold</source>
        <translation>Suspender avance</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continuar</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <source>Single block</source>
        <translation>Bloque a bloque</translation>
    </message>
    <message>
        <source>Feed override -10 %</source>
        <translation>Corrección de avance -10 %</translation>
    </message>
    <message>
        <source>Feed override +10 %</source>
        <translation>Corrección de avance +10 %</translation>
    </message>
    <message>
        <source>Feed override 100 %</source>
        <translation>Corrección de avance 100 %</translation>
    </message>
    <message>
        <source>Feed override %1 %</source>
        <translation>Corrección de avance %1 %</translation>
    </message>
</context>
<context>
    <name>trilho::ui::RunOverlay</name>
    <message>
        <source>Rise time 10-90 % (ms)</source>
        <translation>Tiempo de subida 10-90 % (ms)</translation>
    </message>
    <message>
        <source>Settling time 2 % (ms)</source>
        <translation>Tiempo de establecimiento 2 % (ms)</translation>
    </message>
    <message>
        <source>Settling time +-1 count (ms)</source>
        <translation>Tiempo de establecimiento +-1 cuenta (ms)</translation>
    </message>
    <message>
        <source>Overshoot (%)</source>
        <translation>Sobreimpulso (%)</translation>
    </message>
    <message>
        <source>Peak (mm)</source>
        <translation>Pico (mm)</translation>
    </message>
    <message>
        <source>Peak time (ms)</source>
        <translation>Tiempo de pico (ms)</translation>
    </message>
    <message>
        <source>Steady-state error (counts)</source>
        <translation>Error en estado estacionario (cuentas)</translation>
    </message>
    <message>
        <source>IAE (mm.s)</source>
        <translation>IAE (mm.s)</translation>
    </message>
    <message>
        <source>ITAE (mm.s2)</source>
        <translation>ITAE (mm.s2)</translation>
    </message>
    <message>
        <source>ISE (mm2.s)</source>
        <translation>ISE (mm2.s)</translation>
    </message>
    <message>
        <source>Following error max (mm)</source>
        <translation>Error de seguimiento máx. (mm)</translation>
    </message>
    <message>
        <source>Following error RMS (mm)</source>
        <translation>Error de seguimiento RMS (mm)</translation>
    </message>
    <message>
        <source>Time saturated (ms)</source>
        <translation>Tiempo saturado (ms)</translation>
    </message>
    <message>
        <source>no step</source>
        <translation>sin escalón</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>no alcanzado</translation>
    </message>
    <message>
        <source>time from the step (s)</source>
        <translation>tiempo desde el escalón (s)</translation>
    </message>
    <message>
        <source>displacement (mm)</source>
        <translation>desplazamiento (mm)</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <source>no</source>
        <translation>No</translation>
    </message>
</context>
<context>
    <name>trilho::ui::SelectFileDialog</name>
    <message>
        <source>Select</source>
        <translation>Seleccionar</translation>
    </message>
    <message>
        <source>Examples</source>
        <translation>Ejemplos</translation>
    </message>
    <message>
        <source>Home folder</source>
        <translation>Carpeta personal</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Ruta</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Archivos</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Abrir</translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation>Sa&amp;lir</translation>
    </message>
    <message>
        <source>Files (%1 for other machines not shown)</source>
        <translation>Archivos (%1 de otras máquinas no mostrados)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::SimulationPanel</name>
    <message>
        <source>stuck encoder</source>
        <translation>encoder trabado</translation>
    </message>
    <message>
        <source>amplifier trip</source>
        <translation>falla del amplificador</translation>
    </message>
    <message>
        <source>torn counter reads</source>
        <translation>lecturas partidas del contador</translation>
    </message>
    <message>
        <source>lost counts above %1 counts/s</source>
        <translation>cuentas perdidas por encima de %1 cuentas/s</translation>
    </message>
    <message>
        <source>cable slip %1</source>
        <translation>deslizamiento del cable %1</translation>
    </message>
    <message>
        <source>switch noise %1</source>
        <translation>ruido en los interruptores %1</translation>
    </message>
    <message>
        <source>late ticks up to %1 ms (p %2)</source>
        <translation>ciclos atrasados hasta %1 ms (p %2)</translation>
    </message>
    <message>
        <source>Faults of the simulated rail, for teaching and rehearsal. They act at once; Clear all puts the rail right (acknowledge any alarm after).</source>
        <translation>Fallas del riel simulado, para enseñanza y ensayo. Actúan al instante; Borrar todo restablece el riel (reconozca las alarmas después).</translation>
    </message>
    <message>
        <source>Stuck encoder</source>
        <translation>Encoder trabado</translation>
    </message>
    <message>
        <source>Amplifier trip</source>
        <translation>Disparo del amplificador</translation>
    </message>
    <message>
        <source>Torn counter reads</source>
        <translation>Lecturas partidas del contador</translation>
    </message>
    <message>
        <source>Lost counts above (counts/s, 0 = off):</source>
        <translation>Pérdida de cuentas sobre (cuentas/s, 0 = no):</translation>
    </message>
    <message>
        <source>Cable slip (fraction):</source>
        <translation>Deslizamiento del cable (fracción):</translation>
    </message>
    <message>
        <source>Switch noise (probability per read):</source>
        <translation>Ruido en los interruptores (probabilidad por lectura):</translation>
    </message>
    <message>
        <source>Late servo ticks, up to (ms):</source>
        <translation>Ciclos del servo atrasados, hasta (ms):</translation>
    </message>
    <message>
        <source>Late tick probability:</source>
        <translation>Probabilidad de atraso:</translation>
    </message>
    <message>
        <source>Clear all</source>
        <translation>Borrar todo</translation>
    </message>
</context>
<context>
    <name>trilho::ui::StartScreen</name>
    <message>
        <source>Didactic D.N.C. system for the automatic rail</source>
        <translation>Sistema D.N.C. didáctico para riel automático</translation>
    </message>
    <message>
        <source>University of São Paulo</source>
        <translation>Universidad de São Paulo</translation>
    </message>
    <message>
        <source>Polytechnic School</source>
        <translation>Escuela Politécnica</translation>
    </message>
    <message>
        <source>Numerical Control for the robot&apos;s rail</source>
        <translation>Control Numérico para el riel del robot</translation>
    </message>
    <message>
        <source>Original design, 1996. Rebuilt and finished as trilho.</source>
        <translation>Diseño original de 1996. Reconstruido y terminado como trilho.</translation>
    </message>
    <message>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <source>&amp;Machine:</source>
        <translation>&amp;Máquina:</translation>
    </message>
    <message>
        <source>Robot rail (1996)</source>
        <translation>Riel del robot (1996)</translation>
    </message>
    <message>
        <source>DC-motor XY table</source>
        <translation>Mesa XY con motores CC</translation>
    </message>
    <message>
        <source>Stepper XY plotter</source>
        <translation>Plotter XY con motores paso a paso</translation>
    </message>
</context>
<context>
    <name>trilho::ui::TeachingSwitches</name>
    <message>
        <source>Teaching switches</source>
        <translation>Interruptores didácticos</translation>
    </message>
    <message>
        <source>Anti-windup</source>
        <translation>Anti-windup</translation>
    </message>
    <message>
        <source>Off: the engineered law&apos;s integral winds while the drive is pinned (lesson 17)</source>
        <translation>Apagado: la integral de la ley diseñada se acumula mientras el accionamiento está saturado (lección 17)</translation>
    </message>
    <message>
        <source>Encoder noise (counts)</source>
        <translation>Ruido del encoder (cuentas)</translation>
    </message>
    <message>
        <source>The counter reads up to this many counts off, each tick, from the seed (lesson 18)</source>
        <translation>El contador lee hasta ese número de cuentas de más o de menos, en cada período, a partir de la semilla (lección 18)</translation>
    </message>
    <message>
        <source>DAC quantization (8 bits)</source>
        <translation>Cuantización del DAC (8 bits)</translation>
    </message>
    <message>
        <source>Off: the amplifier gets the loop&apos;s command unrounded (lesson 18)</source>
        <translation>Apagado: el amplificador recibe el comando del lazo sin redondeo (lección 18)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::TermsView</name>
    <message>
        <source>What if: the same run with other gains</source>
        <translation>Y si: el mismo ensayo con otras ganancias</translation>
    </message>
    <message>
        <source>Kp</source>
        <translation>Kp</translation>
    </message>
    <message>
        <source>Ki</source>
        <translation>Ki</translation>
    </message>
    <message>
        <source>Kff</source>
        <translation>Kff</translation>
    </message>
    <message>
        <source>Kd</source>
        <translation>Kd</translation>
    </message>
    <message>
        <source>Re-simulate</source>
        <translation>Volver a simular</translation>
    </message>
    <message>
        <source>Runs the recorded test again from the same start with these gains and adds it to the overlay</source>
        <translation>Ejecuta de nuevo el ensayo grabado desde el mismo inicio con estas ganancias y lo superpone a los demás</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>PWM (%)</source>
        <translation>PWM (%)</translation>
    </message>
    <message>
        <source>DAC codes from 128</source>
        <translation>códigos DAC desde 128</translation>
    </message>
    <message>
        <source>This run has no loop terms (a trace of a program): record a step test to see them.</source>
        <translation>Este ensayo no tiene términos del lazo (es el registro de un programa): grabe una prueba de escalón para verlos.</translation>
    </message>
    <message>
        <source>Run a step test, then choose its column in the table.</source>
        <translation>Ejecute una prueba de escalón y elija su columna en la tabla.</translation>
    </message>
    <message>
        <source>P</source>
        <translation>P</translation>
    </message>
    <message>
        <source>I</source>
        <translation>I</translation>
    </message>
    <message>
        <source>D</source>
        <translation>D</translation>
    </message>
    <message>
        <source>FF</source>
        <translation>FF</translation>
    </message>
    <message>
        <source>sum before the clamp</source>
        <translation>suma antes de la limitación</translation>
    </message>
    <message>
        <source>drive written</source>
        <translation>accionamiento escrito</translation>
    </message>
    <message>
        <source>&lt;b&gt;Tick %1&lt;/b&gt;, t = %2 s, period T = %3 ms</source>
        <translation>&lt;b&gt;Ciclo %1&lt;/b&gt;, t = %2 s, período T = %3 ms</translation>
    </message>
    <message>
        <source>e[k] = r[k] - y[k] = %1 - %2 = &lt;b&gt;%3 mm&lt;/b&gt; (%4 counts)</source>
        <translation>e[k] = r[k] - y[k] = %1 - %2 = &lt;b&gt;%3 mm&lt;/b&gt; (%4 cuentas)</translation>
    </message>
    <message>
        <source>P = Kp e = %1 x %2 = %3 %; I = %4 %; FF = Kff v_ref = %5 %</source>
        <translation>P = Kp e = %1 x %2 = %3 %; I = %4 %; FF = Kff v_ref = %5 %</translation>
    </message>
    <message>
        <source>u = P + I + FF = &lt;b&gt;%1 %&lt;/b&gt; -&gt; clamp -&gt; %2 % -&gt; PWM written %3 %</source>
        <translation>u = P + I + FF = &lt;b&gt;%1 %&lt;/b&gt; -&gt; limitación -&gt; %2 % -&gt; PWM escrito %3 %</translation>
    </message>
    <message>
        <source>The 1996 law: V[k] = floor(128 + Kp e[k] + (Kd / T) (e[k] - e[k-1]) + Ki sum(e) + 0.5), T in ms, clamped by M = F / 100</source>
        <translation>La ley de 1996: V[k] = floor(128 + Kp e[k] + (Kd / T) (e[k] - e[k-1]) + Ki sum(e) + 0.5), T en ms, limitado por M = F / 100</translation>
    </message>
    <message>
        <source>Kp e = %1 x %2 = %3; (Kd / T) (e[k] - e[k-1]) = (%4 / %5) x (%6 - %7) = %8; Ki sum(e) = %9</source>
        <translation>Kp e = %1 x %2 = %3; (Kd / T) (e[k] - e[k-1]) = (%4 / %5) x (%6 - %7) = %8; Ki sum(e) = %9</translation>
    </message>
    <message>
        <source>V = floor(128 + %1 + 0.5) = %2 -&gt; written &lt;b&gt;%3&lt;/b&gt;%4</source>
        <translation>V = floor(128 + %1 + 0.5) = %2 -&gt; escrito &lt;b&gt;%3&lt;/b&gt;%4</translation>
    </message>
    <message>
        <source> (clamped: saturated)</source>
        <translation> (limitado: saturado)</translation>
    </message>
    <message>
        <source>P = Kp e = %1 x %2 = %3 codes</source>
        <translation>P = Kp e = %1 x %2 = %3 códigos</translation>
    </message>
    <message>
        <source>I[k] = I[k-1] + Ki T e[k] = %1 codes (Ki = %2; held while the output is saturated: anti-windup)</source>
        <translation>I[k] = I[k-1] + Ki T e[k] = %1 códigos (Ki = %2; congelado mientras la salida está saturada: anti-windup)</translation>
    </message>
    <message>
        <source>D = -Kd dy/dt (on the measurement, filtered: no kick when the setpoint jumps) = -%1 x %2 = %3 codes</source>
        <translation>D = -Kd dy/dt (sobre la medición, filtrado: sin pico cuando la consigna salta) = -%1 x %2 = %3 códigos</translation>
    </message>
    <message>
        <source>FF = (v_ref + tau a_ref) x 127 / v_max + Kd v_ref = %1 codes (v_ref = %2 mm/s)</source>
        <translation>FF = (v_ref + tau a_ref) x 127 / v_max + Kd v_ref = %1 códigos (v_ref = %2 mm/s)</translation>
    </message>
    <message>
        <source>u = P + I + D + FF = &lt;b&gt;%1 codes&lt;/b&gt; -&gt; clamp and slew limit -&gt; %2 -&gt; DAC = round(128 + u + carried fraction) = &lt;b&gt;%3&lt;/b&gt;%4</source>
        <translation>u = P + I + D + FF = &lt;b&gt;%1 códigos&lt;/b&gt; -&gt; limitación y límite de variación -&gt; %2 -&gt; DAC = round(128 + u + fracción acumulada) = &lt;b&gt;%3&lt;/b&gt;%4</translation>
    </message>
    <message>
        <source> (saturated)</source>
        <translation> (saturado)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::TimelineDialog</name>
    <message>
        <source>History timeline</source>
        <translation>Línea de tiempo del historial</translation>
    </message>
    <message>
        <source>Reading the history...</source>
        <translation>Leyendo el historial...</translation>
    </message>
    <message>
        <source>The history has no alarm, warning, hold, override, mode change or DNC write.</source>
        <translation>El historial no tiene alarma, aviso, espera, corrección de avance, cambio de modo ni escritura DNC.</translation>
    </message>
    <message>
        <source>Marks from the history: %1; times in seconds from its first entry. Click a mark to find it in the list.</source>
        <translation>Marcas del historial: %1; tiempos en segundos desde la primera entrada. Haga clic en una marca para encontrarla en la lista.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::TimelineStrip</name>
    <message>
        <source>Program start</source>
        <translation>Inicio del programa</translation>
    </message>
    <message>
        <source>Program end</source>
        <translation>Fin del programa</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarma</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Aviso</translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation>Reconocido</translation>
    </message>
    <message>
        <source>Held</source>
        <translation>En espera</translation>
    </message>
    <message>
        <source>Resumed</source>
        <translation>Reanudado</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <source>Feed override</source>
        <translation>Corrección de avance</translation>
    </message>
    <message>
        <source>Mode change</source>
        <translation>Cambio de modo</translation>
    </message>
    <message>
        <source>DNC write</source>
        <translation>Escritura DNC</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>línea %1</translation>
    </message>
</context>
<context>
    <name>trilho::ui::WorkbenchWindow</name>
    <message>
        <source>Tuning workbench: %1</source>
        <translation>Banco de sintonía: %1</translation>
    </message>
    <message>
        <source>Margin test (simulated plotter, virtual time)</source>
        <translation>Prueba de margen (plotter simulado, tiempo virtual)</translation>
    </message>
    <message>
        <source>Step test (simulated plant, virtual time)</source>
        <translation>Prueba de escalón (planta simulada, tiempo virtual)</translation>
    </message>
    <message>
        <source>Run margin test</source>
        <translation>Ejecutar prueba de margen</translation>
    </message>
    <message>
        <source>Moves out and back at rising speed, then at rising acceleration, until one loses a step: the profile&apos;s margin against each</source>
        <translation>Movimientos de ida y vuelta a velocidad creciente, luego a aceleración creciente, hasta que uno pierde un paso: el margen del perfil frente a cada una</translation>
    </message>
    <message>
        <source>Change gains during the test</source>
        <translation>Cambiar las ganancias durante la prueba</translation>
    </message>
    <message>
        <source>Bumpless: the integral takes the difference, the drive does not jump</source>
        <translation>Sin salto: la integral absorbe la diferencia, el accionamiento no salta</translation>
    </message>
    <message>
        <source>At (s after the step)</source>
        <translation>En (s tras el escalón)</translation>
    </message>
    <message>
        <source>New Kp</source>
        <translation>Nuevo Kp</translation>
    </message>
    <message>
        <source>New Ki</source>
        <translation>Nuevo Ki</translation>
    </message>
    <message>
        <source>New Kd</source>
        <translation>Nuevo Kd</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Eje</translation>
    </message>
    <message>
        <source>Amplitude (mm)</source>
        <translation>Amplitud del escalón (mm)</translation>
    </message>
    <message>
        <source>The sign is the direction</source>
        <translation>El signo indica el sentido</translation>
    </message>
    <message>
        <source>Speed (% of rapid)</source>
        <translation>Velocidad (% de la máxima)</translation>
    </message>
    <message>
        <source>100 %: a step at the rapid speed; below: a ramp</source>
        <translation>100 %: un escalón a la velocidad máxima; por debajo: una rampa</translation>
    </message>
    <message>
        <source>Control law</source>
        <translation>Ley de control</translation>
    </message>
    <message>
        <source>Engineered</source>
        <translation>Moderna</translation>
    </message>
    <message>
        <source>Classic (1996)</source>
        <translation>Clásico (1996)</translation>
    </message>
    <message>
        <source>Seed 004 (as written)</source>
        <translation>Seed 004 (tal como escrita)</translation>
    </message>
    <message>
        <source>Seed 004 signed</source>
        <translation>Seed 004 con signo</translation>
    </message>
    <message>
        <source>Seed 004 as written: u = 100 (b0 |e| + b1 |e_prev|), the direction bit fixed for the move (past the target it drives on); signed: the same gains on the signed error (it drives back); engineered: feed-forward and PI</source>
        <translation>Seed 004 tal como escrita: u = 100 (b0 |e| + b1 |e_ant|), el bit de dirección fijo durante el movimiento (pasado el objetivo, sigue accionando); con signo: las mismas ganancias sobre el error con signo (acciona de vuelta); de ingeniería: feed-forward y PI</translation>
    </message>
    <message>
        <source>Period (ms)</source>
        <translation>Período (ms)</translation>
    </message>
    <message>
        <source>The 1996 law ran at 10 ms: its gains are per tick, so at 1 ms they act ten times harder (a lesson, not a setting)</source>
        <translation>La ley de 1996 corría a 10 ms: sus ganancias son por ciclo, así que a 1 ms actúan diez veces más fuerte (una lección, no un ajuste)</translation>
    </message>
    <message>
        <source>Seed 004 ran at 5 ms: its b0 and b1 are per tick, so at another period the same numbers are another law (a lesson, not a setting)</source>
        <translation>El seed 004 corría a 5 ms: sus b0 y b1 son por período, así que en otro período los mismos números son otra ley (una lección, no un ajuste)</translation>
    </message>
    <message>
        <source>Mass factor</source>
        <translation>Factor de masa</translation>
    </message>
    <message>
        <source>The plant&apos;s moving mass times this; the loop is not told</source>
        <translation>La masa móvil de la planta por este factor; el lazo no lo sabe</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Semilla</translation>
    </message>
    <message>
        <source>Run step</source>
        <translation>Ejecutar escalón</translation>
    </message>
    <message>
        <source>1996 law against engineered</source>
        <translation>Ley de 1996 frente a la moderna</translation>
    </message>
    <message>
        <source>The same move with the 1996 law at its 10 ms and its gains, and with the engineered law</source>
        <translation>El mismo movimiento con la ley de 1996, con sus 10 ms y sus ganancias, y con la ley moderna</translation>
    </message>
    <message>
        <source>Identification and autotune</source>
        <translation>Identificación y autoajuste</translation>
    </message>
    <message>
        <source>Identify the plant</source>
        <translation>Identificar la planta</translation>
    </message>
    <message>
        <source>At most 3 s of machine time, within 100 mm, back to the start within a count</source>
        <translation>Como máximo 3 s de tiempo de máquina, dentro de 100 mm, de vuelta al inicio a menos de una cuenta</translation>
    </message>
    <message>
        <source>Autotune</source>
        <translation>Autoajuste</translation>
    </message>
    <message>
        <source>Identify, design (SIMC), predict, then verify with a 10 mm step and a 1000 mm move</source>
        <translation>Identifica, diseña (SIMC), predice y luego verifica con un escalón de 10 mm y un movimiento de 1000 mm</translation>
    </message>
    <message>
        <source>Identify the axis, design (SIMC PI), predict, then verify with a 10 mm step and a 100 mm move</source>
        <translation>Identificar el eje, diseñar (PI SIMC), predecir y luego verificar con un escalón de 10 mm y un movimiento de 100 mm</translation>
    </message>
    <message>
        <source>Relay experiment (Ziegler-Nichols)</source>
        <translation>Experimento del relé (Ziegler-Nichols)</translation>
    </message>
    <message>
        <source>To teach with, never the default: a relay of +-3 codes provokes a limit cycle, Ziegler-Nichols gains from it, beside the model-based gains, both on the same 10 mm step</source>
        <translation>Para enseñar, nunca por defecto: un relé de +-3 códigos provoca un ciclo límite, ganancias de Ziegler-Nichols a partir de él, junto a las ganancias basadas en el modelo, ambas en el mismo escalón de 10 mm</translation>
    </message>
    <message>
        <source>Save tuned profile...</source>
        <translation>Guardar perfil sintonizado...</translation>
    </message>
    <message>
        <source>Runs</source>
        <translation>Ensayos</translation>
    </message>
    <message>
        <source>Save run...</source>
        <translation>Guardar ensayo...</translation>
    </message>
    <message>
        <source>Load run...</source>
        <translation>Cargar ensayo...</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Quitar</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Export lab sheet...</source>
        <translation>&amp;Exportar hoja de laboratorio...</translation>
    </message>
    <message>
        <source>The runs shown, overlaid, with their gains, law, period, payload and metrics side by side: one A4 page, PDF or PNG</source>
        <translation>Los ensayos mostrados, superpuestos, con sus ganancias, ley, período, carga y métricas lado a lado: una página A4, PDF o PNG</translation>
    </message>
    <message>
        <source>Margin</source>
        <translation>Margen</translation>
    </message>
    <message>
        <source>Responses</source>
        <translation>Respuestas</translation>
    </message>
    <message>
        <source>P, I, D terms</source>
        <translation>Términos P, I, D</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modelo</translation>
    </message>
    <message>
        <source>Poles</source>
        <translation>Polos</translation>
    </message>
    <message>
        <source>Prediction</source>
        <translation>Predicción</translation>
    </message>
    <message>
        <source>Disturbance</source>
        <translation>Perturbación</translation>
    </message>
    <message>
        <source>b0 (per rad)</source>
        <translation>b0 (por rad)</translation>
    </message>
    <message>
        <source>Kp</source>
        <translation>Kp</translation>
    </message>
    <message>
        <source>b1 (per rad)</source>
        <translation>b1 (por rad)</translation>
    </message>
    <message>
        <source>Ki</source>
        <translation>Ki</translation>
    </message>
    <message>
        <source>Kd</source>
        <translation>Kd</translation>
    </message>
    <message>
        <source>Kff</source>
        <translation>Kff</translation>
    </message>
    <message>
        <source>Seed 004: u = 100 (b0 e + b1 e_prev) % PWM, e in rad of the motor, per tick: 100 (b0 + b1) is its proportional gain, -100 b1 a difference of e per tick</source>
        <translation>Seed 004: u = 100 (b0 e + b1 e_ant) % de PWM, e en rad del motor, por período: 100 (b0 + b1) es su ganancia proporcional, -100 b1 una diferencia de e por período</translation>
    </message>
    <message>
        <source>1996</source>
        <translation>1996</translation>
    </message>
    <message>
        <source>engineered</source>
        <translation>moderna</translation>
    </message>
    <message>
        <source>seed 004</source>
        <translation>seed 004</translation>
    </message>
    <message>
        <source>seed 004 signed</source>
        <translation>seed 004 con signo</translation>
    </message>
    <message>
        <source>%1 %2, %3 mm at %4 ms, mass x%5</source>
        <translation>%1 %2, %3 mm a %4 ms, masa x%5</translation>
    </message>
    <message>
        <source>, then Kp %1 Ki %2 Kd %3 from %4 s</source>
        <translation>, luego Kp %1 Ki %2 Kd %3 desde %4 s</translation>
    </message>
    <message>
        <source>Running in virtual time...</source>
        <translation>Ejecutando en tiempo virtual...</translation>
    </message>
    <message>
        <source>Run %1 done.</source>
        <translation>Ensayo %1 terminado.</translation>
    </message>
    <message>
        <source>Run %1 stopped: %2</source>
        <translation>Ensayo %1 detenido: %2</translation>
    </message>
    <message>
        <source>The gain change never came (%1): the run had one set of gains.</source>
        <translation>El cambio de ganancias no llegó (%1): la ejecución tuvo un solo juego de ganancias.</translation>
    </message>
    <message>
        <source>what if (from run %1): %2</source>
        <translation>y si (del ensayo %1): %2</translation>
    </message>
    <message>
        <source>Identified: fit %1 % on held-out velocity.</source>
        <translation>Identificado: ajuste del %1 % en la velocidad de validación.</translation>
    </message>
    <message>
        <source>Model refused: %1</source>
        <translation>Modelo rechazado: %1</translation>
    </message>
    <message>
        <source>Autotune passed in %1 s of machine time.</source>
        <translation>Autoajuste aprobado en %1 s de tiempo de máquina.</translation>
    </message>
    <message>
        <source>Autotune failed: %1</source>
        <translation>Autoajuste fallido: %1</translation>
    </message>
    <message>
        <source>Relay: Ku %1 code/mm, Tu %2 ms.</source>
        <translation>Relé: Ku %1 código/mm, Tu %2 ms.</translation>
    </message>
    <message>
        <source>Relay experiment failed: %1</source>
        <translation>El experimento del relé falló: %1</translation>
    </message>
    <message>
        <source>Margin test done: speed margin %1, acceleration margin %2.</source>
        <translation>Prueba de margen hecha: margen de velocidad %1, margen de aceleración %2.</translation>
    </message>
    <message>
        <source>Margin test refused: %1</source>
        <translation>Prueba de margen rechazada: %1</translation>
    </message>
    <message>
        <source>No run is selected.</source>
        <translation>Ningún ensayo seleccionado.</translation>
    </message>
    <message>
        <source>Saving %1...</source>
        <translation>Guardando %1...</translation>
    </message>
    <message>
        <source>Saved %1 and %2.</source>
        <translation>Guardados %1 y %2.</translation>
    </message>
    <message>
        <source>Loading %1...</source>
        <translation>Cargando %1...</translation>
    </message>
    <message>
        <source>Load run</source>
        <translation>Cargar ensayo</translation>
    </message>
    <message>
        <source>%1: the run has no samples</source>
        <translation>%1: el ensayo no tiene muestras</translation>
    </message>
    <message>
        <source>The run&apos;s events are not shown: %1</source>
        <translation>Los eventos de la ejecución no se muestran: %1</translation>
    </message>
    <message>
        <source>Save run</source>
        <translation>Guardar ensayo</translation>
    </message>
    <message>
        <source>Run records (*.csv)</source>
        <translation>Registros de ensayo (*.csv)</translation>
    </message>
    <message>
        <source>Run records and traces (*.csv)</source>
        <translation>Registros de ensayo y trazas (*.csv)</translation>
    </message>
    <message>
        <source>Save tuned profile</source>
        <translation>Guardar perfil sintonizado</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Perfiles de máquina (*.json)</translation>
    </message>
    <message>
        <source>Saved %1: trilho-cli run --machine %1 uses it.</source>
        <translation>Guardado %1: trilho-cli run --machine %1 lo usa.</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: a lab sheet is a .pdf or a .png file</source>
        <translation>&apos;%1&apos;: una hoja de laboratorio es un archivo .pdf o .png</translation>
    </message>
    <message>
        <source>No run is shown: there is nothing to put on a lab sheet.</source>
        <translation>No se muestra ningún ensayo: no hay nada que poner en una hoja de laboratorio.</translation>
    </message>
    <message>
        <source>%1 runs are shown: at most %2 fit one sheet (untick some in the runs&apos; list)</source>
        <translation>Se muestran %1 ensayos: caben como máximo %2 en una hoja (desmarque algunos en la lista de ensayos)</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Imagen PNG (*.png)</translation>
    </message>
    <message>
        <source>Export lab sheet</source>
        <translation>Exportar hoja de laboratorio</translation>
    </message>
    <message>
        <source>Lab sheet written: %1</source>
        <translation>Hoja de laboratorio escrita: %1</translation>
    </message>
</context>
<context>
    <name>trilho::ui::XyMainWindow</name>
    <message>
        <source>MANUAL</source>
        <translation>MANUAL</translation>
    </message>
    <message>
        <source>AUTOMATIC - ready</source>
        <translation>AUTOMÁTICO - listo</translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation>REFERENCIANDO</translation>
    </message>
    <message>
        <source>RUNNING</source>
        <translation>EJECUTANDO</translation>
    </message>
    <message>
        <source>DWELL</source>
        <translation>ESPERA</translation>
    </message>
    <message>
        <source>PAUSED</source>
        <translation>PAUSADO</translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation>ALARMA</translation>
    </message>
    <message>
        <source>E-STOP LATCHED</source>
        <translation>EMERGENCIA ACTIVADA</translation>
    </message>
    <message>
        <source>Stop the machine before changing the connection.</source>
        <translation>Detenga la máquina antes de cambiar la conexión.</translation>
    </message>
    <message>
        <source>Feed override %1 %</source>
        <translation>Corrección de avance %1 %</translation>
    </message>
    <message>
        <source>Loading %1 (%2 MB)...</source>
        <translation>Cargando %1 (%2 MB)...</translation>
    </message>
    <message>
        <source>the pen lifts and the carriage runs to the origin sensors, where both axes are zeroed (0, 0).</source>
        <translation>la pluma sube y el carro va hasta los sensores de origen, donde los dos ejes se ponen a cero (0, 0).</translation>
    </message>
    <message>
        <source>the DC table has no home switch: it travels at full speed to (0, 0), its origin (where it stood at power-on).</source>
        <translation>la mesa CC no tiene interruptor de referencia: va a velocidad máxima hasta (0, 0), su origen (donde estaba al encenderla).</translation>
    </message>
    <message>
        <source>the DC table has no home switch: its origin is where it stood at power-on, and nothing moves.</source>
        <translation>la mesa CC no tiene interruptor de referencia: su origen es donde estaba al encenderla, y nada se mueve.</translation>
    </message>
    <message>
        <source> (first programmed move to (%1, %2) mm)</source>
        <translation> (primer movimiento programado a (%1, %2) mm)</translation>
    </message>
    <message>
        <source>It starts the program where homing leaves it, at the origin (0.0, 0.0) mm, where every program starts%1.</source>
        <translation>Empieza el programa donde la deja la referencia, en el origen (0.0, 0.0) mm, donde empieza todo programa%1.</translation>
    </message>
    <message>
        <source>It starts the program where it stands, at the origin (0.0, 0.0) mm, where every program starts%1.</source>
        <translation>Empieza el programa donde está, en el origen (0.0, 0.0) mm, donde empieza todo programa%1.</translation>
    </message>
    <message>
        <source>The machine travels at full speed from (%1, %2) mm to the origin (0.0, 0.0) mm, where every program starts, then runs it%3.</source>
        <translation>La máquina va a velocidad máxima de (%1, %2) mm hasta el origen (0.0, 0.0) mm, donde empieza todo programa, y luego lo ejecuta%3.</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automático</translation>
    </message>
    <message>
        <source>Automatic homes the machine first: %1 Go on?</source>
        <translation>El modo automático primero referencia la máquina: %1 ¿Continuar?</translation>
    </message>
    <message>
        <source>Home: stop the machine (or reset the E-stop, acknowledge the alarm) first.</source>
        <translation>Referenciar: detenga la máquina (o rearme la emergencia, reconozca la alarma) antes.</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Referenciar</translation>
    </message>
    <message>
        <source>Home the machine? %1</source>
        <translation>¿Referenciar la máquina? %1</translation>
    </message>
    <message>
        <source>Run %1? %2%3</source>
        <translation>¿Ejecutar %1? %2%3</translation>
    </message>
    <message>
        <source>Its position is not known, so it homes first: %1 </source>
        <translation>La posición no se conoce, así que primero hace la referencia: %1 </translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation>Inicio de ciclo</translation>
    </message>
    <message>
        <source>Open program</source>
        <translation>Abrir programa</translation>
    </message>
    <message>
        <source>G-code programs (*.G *.g)</source>
        <translation>Programas G (*.G *.g)</translation>
    </message>
    <message>
        <source>The history could not be written: %1</source>
        <translation>No se pudo escribir el historial: %1</translation>
    </message>
    <message>
        <source>The simulated machine started again at its origin: the run that was going is lost.</source>
        <translation>La máquina simulada volvió a empezar en su origen: la ejecución en curso se perdió.</translation>
    </message>
    <message>
        <source>Positions are unknown until homed: the plotter&apos;s protocol has no question the board answers with where it stands.</source>
        <translation>Las posiciones son desconocidas hasta la referencia: el protocolo del plotter no tiene pregunta a la que la placa responda dónde está.</translation>
    </message>
    <message>
        <source>Positions are unknown until homed; the board is asked which set point it last ran.</source>
        <translation>Las posiciones son desconocidas hasta la referencia; se pregunta a la placa el último punto de consigna que ejecutó.</translation>
    </message>
    <message>
        <source>unknown until homed</source>
        <translation>desconocida hasta la referencia</translation>
    </message>
    <message>
        <source>the board&apos;s last set point, not homed</source>
        <translation>último punto de consigna de la placa, sin referencia</translation>
    </message>
    <message>
        <source>planned, unconfirmed: the seed&apos;s board answers nothing</source>
        <translation>planificada, sin confirmar: la placa del seed no responde nada</translation>
    </message>
    <message>
        <source>Block N%1, line %2</source>
        <translation>Bloque N%1, línea %2</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Línea %1</translation>
    </message>
    <message>
        <source>Simulated machine</source>
        <translation>Máquina simulada</translation>
    </message>
    <message>
        <source>LINK LOST</source>
        <translation>ENLACE PERDIDO</translation>
    </message>
    <message>
        <source>link up</source>
        <translation>enlace activo</translation>
    </message>
    <message>
        <source>port open; the seed&apos;s board answers nothing: position planned, unconfirmed</source>
        <translation>puerto abierto; la placa del seed no responde nada: posición planificada, sin confirmar</translation>
    </message>
    <message>
        <source>port open, no answer yet</source>
        <translation>puerto abierto, aún sin respuesta</translation>
    </message>
    <message>
        <source>%1 at %2 bit/s: %3 - packets %4, RESENDs %5, timeouts %6</source>
        <translation>%1 a %2 bit/s: %3 - paquetes %4, RESENDs %5, tiempos agotados %6</translation>
    </message>
    <message>
        <source>%1 at %2 bit/s: %3 - set points sent %4 (no acknowledgement)</source>
        <translation>%1 a %2 bit/s: %3 - consignas enviadas %4 (sin confirmación)</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <source>Simulated machine (no hardware)</source>
        <translation>Máquina simulada (sin hardware)</translation>
    </message>
    <message>
        <source>Board on a serial port</source>
        <translation>Placa en un puerto serie</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Puerto</translation>
    </message>
    <message>
        <source>Bit rate</source>
        <translation>Velocidad (bit/s)</translation>
    </message>
    <message>
        <source>trilho - %1</source>
        <translation>trilho - %1</translation>
    </message>
    <message>
        <source>Open...</source>
        <translation>Abrir...</translation>
    </message>
    <message>
        <source>Automatic (home)</source>
        <translation>Automático (referencia)</translation>
    </message>
    <message>
        <source>Cycle start (F5)</source>
        <translation>Inicio de ciclo (F5)</translation>
    </message>
    <message>
        <source>Feed hold (F6)</source>
        <translation>Suspender avance (F6)</translation>
    </message>
    <message>
        <source>Continue (F7)</source>
        <translation>Continuar (F7)</translation>
    </message>
    <message>
        <source>Stop (F8)</source>
        <translation>Detener (F8)</translation>
    </message>
    <message>
        <source>Single block (F9)</source>
        <translation>Bloque a bloque (F9)</translation>
    </message>
    <message>
        <source>Feed hold</source>
        <translation>Suspender avance</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continuar</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <source>Single block</source>
        <translation>Bloque a bloque</translation>
    </message>
    <message>
        <source>Feed override -10 %</source>
        <translation>Corrección de avance -10 %</translation>
    </message>
    <message>
        <source>Feed override +10 %</source>
        <translation>Corrección de avance +10 %</translation>
    </message>
    <message>
        <source>Feed override 100 %</source>
        <translation>Corrección de avance 100 %</translation>
    </message>
    <message>
        <source>&amp;Open program...</source>
        <translation>&amp;Abrir programa...</translation>
    </message>
    <message>
        <source>&amp;Connection...</source>
        <translation>&amp;Conexión...</translation>
    </message>
    <message>
        <source>Ca&amp;libration...</source>
        <translation>Ca&amp;libración...</translation>
    </message>
    <message>
        <source>Polygon from &amp;points...</source>
        <translation>Polígono por &amp;puntos...</translation>
    </message>
    <message>
        <source>The plotter has no encoder: its workbench is the speed and acceleration margin test against lost steps</source>
        <translation>El plotter no tiene encoder: su banco es la prueba de margen de velocidad y aceleración frente a pasos perdidos</translation>
    </message>
    <message>
        <source>Program: %1</source>
        <translation>Programa: %1</translation>
    </message>
    <message>
        <source>No program loaded</source>
        <translation>Ningún programa cargado</translation>
    </message>
</context>
<context>
    <name>trilho::ui::XyPlots</name>
    <message>
        <source>x set point</source>
        <translation>consigna x</translation>
    </message>
    <message>
        <source>x planned (unconfirmed)</source>
        <translation>posición x planificada (sin confirmar)</translation>
    </message>
    <message>
        <source>x: the board&apos;s last set point</source>
        <translation>x: la última consigna de la placa</translation>
    </message>
    <message>
        <source>x position</source>
        <translation>posición x</translation>
    </message>
    <message>
        <source>y set point</source>
        <translation>consigna y</translation>
    </message>
    <message>
        <source>y planned (unconfirmed)</source>
        <translation>posición y planificada (sin confirmar)</translation>
    </message>
    <message>
        <source>y: the board&apos;s last set point</source>
        <translation>y: la última consigna de la placa</translation>
    </message>
    <message>
        <source>y position</source>
        <translation>posición y</translation>
    </message>
    <message>
        <source>x set-point speed</source>
        <translation>velocidad de la consigna x</translation>
    </message>
    <message>
        <source>x speed: not reported on a line</source>
        <translation>velocidad x: no informada en la línea</translation>
    </message>
    <message>
        <source>y set-point speed</source>
        <translation>velocidad de la consigna y</translation>
    </message>
    <message>
        <source>y speed: not reported on a line</source>
        <translation>velocidad y: no informada en la línea</translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation>posición (mm)</translation>
    </message>
    <message>
        <source>speed (mm/s)</source>
        <translation>velocidad (mm/s)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::XySimulationPanel</name>
    <message>
        <source>%1 axis jammed</source>
        <translation>eje %1 trabado</translation>
    </message>
    <message>
        <source>%1 encoder stuck</source>
        <translation>encóder %1 detenido</translation>
    </message>
    <message>
        <source>lost steps above %1 steps/s</source>
        <translation>pasos perdidos por encima de %1 pasos/s</translation>
    </message>
    <message>
        <source>origin sensors dead</source>
        <translation>sensores de origen muertos</translation>
    </message>
    <message>
        <source>Faults of the simulated plotter, for teaching and rehearsal. They act at once; Clear all puts the plotter right (home again after lost steps).</source>
        <translation>Fallas del plotter simulado, para enseñanza y práctica. Actúan al instante; Borrar todo deja el plotter en orden (vuelva a referenciar tras pasos perdidos).</translation>
    </message>
    <message>
        <source>Lost steps above (steps/s, 0 = off):</source>
        <translation>Pasos perdidos por encima de (pasos/s, 0 = apagado):</translation>
    </message>
    <message>
        <source>Origin sensors dead (homing gives up)</source>
        <translation>Sensores de origen muertos (la referencia se rinde)</translation>
    </message>
    <message>
        <source>Faults of the simulated table, for teaching and rehearsal. They act at once; Clear all puts the table right (acknowledge any alarm after).</source>
        <translation>Fallas de la mesa simulada, para enseñanza y práctica. Actúan al instante; Borrar todo deja la mesa en orden (reconozca después cualquier alarma).</translation>
    </message>
    <message>
        <source>X axis jammed</source>
        <translation>Eje X trabado</translation>
    </message>
    <message>
        <source>Y axis jammed</source>
        <translation>Eje Y trabado</translation>
    </message>
    <message>
        <source>X encoder stuck</source>
        <translation>Encóder X detenido</translation>
    </message>
    <message>
        <source>Y encoder stuck</source>
        <translation>Encóder Y detenido</translation>
    </message>
    <message>
        <source>Clear all</source>
        <translation>Borrar todo</translation>
    </message>
</context>
</TS>
