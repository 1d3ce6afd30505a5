<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
<context>
    <name>Diagnostic</name>
    <message>
        <source>every line must start with n (found '%2')</source>
        <translation>Erro: Toda linha deve iniciar com n.</translation>
    </message>
    <message>
        <source>wrong n sequence on line %1: must be greater than %3</source>
        <translation>Erro: Seqüência n errada na linha %1</translation>
    </message>
    <message>
        <source>sequence number alone on line %1</source>
        <translation>Erro: Seqüência n sozinha na linha %1</translation>
    </message>
    <message>
        <source>separating spaces required on line %1 (found '%2')</source>
        <translation>Erro: Espaços para separação requeridos na linha %1</translation>
    </message>
    <message>
        <source>there can be no more commands after %2 on line %1</source>
        <translation>Erro: Não pode haver mais comandos após %2 na linha %1</translation>
    </message>
    <message>
        <source>g00 requires an x word on line %1</source>
        <translation>Erro: g00 requer comando x na linha %1</translation>
    </message>
    <message>
        <source>g01 requires an x word on line %1</source>
        <translation>Erro: g01 requer comando x na linha %1</translation>
    </message>
    <message>
        <source>g04 without x word (time) on line %1</source>
        <translation>Erro: g04 sem comando x (tempo) na linha %1</translation>
    </message>
    <message>
        <source>g92 requires an x word on line %1</source>
        <translation>Erro: g92 requer comando x na linha %1</translation>
    </message>
    <message>
        <source>m03 without x word (block) on line %1</source>
        <translation>Erro: m03 sem comando x (linha) na linha %1</translation>
    </message>
    <message>
        <source>invalid value after g04 on line %1: the time %2 is negative</source>
        <translation>Erro: Caracter inválido após g04 na linha %1</translation>
    </message>
    <message>
        <source>invalid value after m03 on line %1: the block %2 is negative</source>
        <translation>Erro: Caracter inválido após m03 na linha %1</translation>
    </message>
    <message>
        <source>negative f command impossible on line %1 (%2)</source>
        <translation>Erro: Comando f negativo impossível na linha %1</translation>
    </message>
    <message>
        <source>invalid g command on line %1 (%2)</source>
        <translation>Erro: Comando g inválido na linha %1</translation>
    </message>
    <message>
        <source>invalid m command on line %1 (%2)</source>
        <translation>Erro: Comando m inválido na linha %1</translation>
    </message>
    <message>
        <source>g01 or g00 not defined on line %1</source>
        <translation>Erro: g01 ou g00 não definidos na linha %1</translation>
    </message>
    <message>
        <source>g01 needs f defined on line %1</source>
        <translation>Erro: g01 precisa de f definido na linha %1</translation>
    </message>
    <message>
        <source>invalid character or g00 does not take f on line %1</source>
        <translation>Erro: Caracter inválido ou g00 não requer f na linha %1</translation>
    </message>
    <message>
        <source>invalid character on line %1: '%2'</source>
        <translation>Erro: Caracter inválido na linha %1 ('%2')</translation>
    </message>
    <message>
        <source>invalid character on line %1: malformed number '%2'</source>
        <translation>Erro: Caracter inválido na linha %1 (número malformado '%2')</translation>
    </message>
    <message>
        <source>invalid character on line %1: '%2' must have exactly %3 digits</source>
        <translation>Erro: Caracter inválido na linha %1 ('%2' deve ter %3 dígitos)</translation>
    </message>
    <message>
        <source>invalid character on line %1: comment not closed</source>
        <translation>Erro: Caracter inválido na linha %1 (comentário não fechado)</translation>
    </message>
    <message>
        <source>invalid character on line %1: word '%2' repeated</source>
        <translation>Erro: Caracter inválido na linha %1 (comando '%2' repetido)</translation>
    </message>
    <message>
        <source>invalid character on line %1: n must be the first word ('%2')</source>
        <translation>Erro: Caracter inválido na linha %1 (n deve ser o primeiro comando: '%2')</translation>
    </message>
    <message>
        <source>invalid value after m03 on line %1: '%2' is not a block number</source>
        <translation>Erro: Caracter inválido após m03 na linha %1 ('%2')</translation>
    </message>
    <message>
        <source>invalid character on line %1: number '%2' longer than %3 digits</source>
        <translation>Erro: Caracter inválido na linha %1 (número '%2' com mais de %3 dígitos)</translation>
    </message>
    <message>
        <source>program requires m02 (END) at the end</source>
        <translation>Erro: Programa requer m02 (END) no final</translation>
    </message>
    <message>
        <source>invalid GO TO on line %1: block n%2 does not exist</source>
        <translation>Erro: GO TO Inválido na linha %1 (bloco n%2 não existe)</translation>
    </message>
    <message>
        <source>feed f%2 out of range on line %1: must be above 0 and at most 100 %</source>
        <translation>Erro: Comando f fora da faixa na linha %1 (f%2; deve ser maior que 0 e no máximo 100 %)</translation>
    </message>
    <message>
        <source>target %2 mm on line %1 is beyond the soft limit %3 mm</source>
        <translation>Erro: Posição %2 mm na linha %1 além do limite de curso %3 mm</translation>
    </message>
    <message>
        <source>axis %2 does not exist on this machine (line %1)</source>
        <translation>Erro: Eixo %2 não existe nesta máquina (linha %1)</translation>
    </message>
    <message>
        <source>Compilation completed successfully</source>
        <translation>Compilação completada com sucesso !</translation>
    </message>
    <message>
        <source>%1 compile error(s)</source>
        <translation>Há %1 erro(s) de compilação !</translation>
    </message>
</context>
</TS>
