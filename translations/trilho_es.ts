<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es">
<context>
    <name>Diagnostic</name>
    <message>
        <source>every line must start with n (found '%2')</source>
        <translation>toda línea debe comenzar con n (se encontró '%2')</translation>
    </message>
    <message>
        <source>wrong n sequence on line %1: must be greater than %3</source>
        <translation>secuencia n incorrecta en la línea %1: debe ser mayor que %3</translation>
    </message>
    <message>
        <source>sequence number alone on line %1</source>
        <translation>número de secuencia solo en la línea %1</translation>
    </message>
    <message>
        <source>separating spaces required on line %1 (found '%2')</source>
        <translation>se requieren espacios de separación en la línea %1 (se encontró '%2')</translation>
    </message>
    <message>
        <source>there can be no more commands after %2 on line %1</source>
        <translation>no puede haber más comandos después de %2 en la línea %1</translation>
    </message>
    <message>
        <source>g00 requires an x word on line %1</source>
        <translation>g00 requiere comando x en la línea %1</translation>
    </message>
    <message>
        <source>g01 requires an x word on line %1</source>
        <translation>g01 requiere comando x en la línea %1</translation>
    </message>
    <message>
        <source>g04 without x word (time) on line %1</source>
        <translation>g04 sin comando x (tiempo) en la línea %1</translation>
    </message>
    <message>
        <source>g92 requires an x word on line %1</source>
        <translation>g92 requiere comando x en la línea %1</translation>
    </message>
    <message>
        <source>m03 without x word (block) on line %1</source>
        <translation>m03 sin comando x (bloque) en la línea %1</translation>
    </message>
    <message>
        <source>invalid value after g04 on line %1: the time %2 is negative</source>
        <translation>valor inválido después de g04 en la línea %1: el tiempo %2 es negativo</translation>
    </message>
    <message>
        <source>invalid value after m03 on line %1: the block %2 is negative</source>
        <translation>valor inválido después de m03 en la línea %1: el bloque %2 es negativo</translation>
    </message>
    <message>
        <source>negative f command impossible on line %1 (%2)</source>
        <translation>comando f negativo imposible en la línea %1 (%2)</translation>
    </message>
    <message>
        <source>invalid g command on line %1 (%2)</source>
        <translation>comando g inválido en la línea %1 (%2)</translation>
    </message>
    <message>
        <source>invalid m command on line %1 (%2)</source>
        <translation>comando m inválido en la línea %1 (%2)</translation>
    </message>
    <message>
        <source>g01 or g00 not defined on line %1</source>
        <translation>g01 o g00 no definidos en la línea %1</translation>
    </message>
    <message>
        <source>g01 needs f defined on line %1</source>
        <translation>g01 necesita f definido en la línea %1</translation>
    </message>
    <message>
        <source>invalid character or g00 does not take f on line %1</source>
        <translation>carácter inválido o g00 no admite f en la línea %1</translation>
    </message>
    <message>
        <source>invalid character on line %1: '%2'</source>
        <translation>carácter inválido en la línea %1: '%2'</translation>
    </message>
    <message>
        <source>invalid character on line %1: malformed number '%2'</source>
        <translation>carácter inválido en la línea %1: número mal formado '%2'</translation>
    </message>
    <message>
        <source>invalid character on line %1: '%2' must have exactly %3 digits</source>
        <translation>carácter inválido en la línea %1: '%2' debe tener exactamente %3 dígitos</translation>
    </message>
    <message>
        <source>invalid character on line %1: comment not closed</source>
        <translation>carácter inválido en la línea %1: comentario sin cerrar</translation>
    </message>
    <message>
        <source>invalid character on line %1: word '%2' repeated</source>
        <translation>carácter inválido en la línea %1: palabra '%2' repetida</translation>
    </message>
    <message>
        <source>invalid character on line %1: n must be the first word ('%2')</source>
        <translation>carácter inválido en la línea %1: n debe ser la primera palabra ('%2')</translation>
    </message>
    <message>
        <source>invalid value after m03 on line %1: '%2' is not a block number</source>
        <translation>valor inválido después de m03 en la línea %1: '%2' no es un número de bloque</translation>
    </message>
    <message>
        <source>invalid character on line %1: number '%2' longer than %3 digits</source>
        <translation>carácter inválido en la línea %1: número '%2' de más de %3 dígitos</translation>
    </message>
    <message>
        <source>program requires m02 (END) at the end</source>
        <translation>el programa requiere m02 (END) al final</translation>
    </message>
    <message>
        <source>invalid GO TO on line %1: block n%2 does not exist</source>
        <translation>GO TO inválido en la línea %1: el bloque n%2 no existe</translation>
    </message>
    <message>
        <source>feed f%2 out of range on line %1: must be above 0 and at most 100 %</source>
        <translation>avance f%2 fuera de rango en la línea %1: debe ser mayor que 0 y como máximo 100 %</translation>
    </message>
    <message>
        <source>target %2 mm on line %1 is beyond the soft limit %3 mm</source>
        <translation>destino %2 mm en la línea %1 más allá del límite de recorrido %3 mm</translation>
    </message>
    <message>
        <source>axis %2 does not exist on this machine (line %1)</source>
        <translation>el eje %2 no existe en esta máquina (línea %1)</translation>
    </message>
    <message>
        <source>Compilation completed successfully</source>
        <translation>Compilación completada con éxito</translation>
    </message>
    <message>
        <source>%1 compile error(s)</source>
        <translation>%1 error(es) de compilación</translation>
    </message>
</context>
</TS>
