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
<context>
    <name>Controller</name>
    <message>
        <source>%1: Positioning to x=%2 at maximum speed.</source>
        <translation>%1: Posicionamento para x=%2 com velocidade máxima.</translation>
    </message>
    <message>
        <source>%1: Positioning to x=%2 at %3% of maximum speed.</source>
        <translation>%1: Posicionamento para x=%2 com %3% da velocidade máxima.</translation>
    </message>
    <message>
        <source>%1: Waiting %2 seconds.</source>
        <translation>%1: Aguardando %2 segundos.</translation>
    </message>
    <message>
        <source>%1: Change to absolute coordinates.</source>
        <translation>%1: Mudança para coordenada absoluta.</translation>
    </message>
    <message>
        <source>%1: Change to incremental coordinates.</source>
        <translation>%1: Mudança para coordenada incremental.</translation>
    </message>
    <message>
        <source>%1: System zero changed to x=%2.</source>
        <translation>%1: Mudança do zero do sistema para x=%2.</translation>
    </message>
    <message>
        <source>%1: Return to the rail's absolute zero.</source>
        <translation>%1: Retorno para zero absoluto do trilho.</translation>
    </message>
    <message>
        <source>%1: Feed set to %3% of maximum speed.</source>
        <translation>%1: Avanço mudado para %3% da velocidade máxima.</translation>
    </message>
    <message>
        <source>%1: Waiting for the Continue key.</source>
        <translation>%1: Aguardando tecla Continua.</translation>
    </message>
    <message>
        <source>%1: Program jumped to line %2.</source>
        <translation>%1: Programa desviado para linha %2.</translation>
    </message>
    <message>
        <source>Program finished !</source>
        <translation>Programa finalizado !</translation>
    </message>
    <message>
        <source>There are %2 compile error(s)! Nothing moved.</source>
        <translation>Há %2 erro(s) de compilação! Nada foi movido.</translation>
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
        <translation>Plataforma indo para o centro do trilho.</translation>
    </message>
    <message>
        <source>Homing done: platform at the rail centre.</source>
        <translation>Plataforma no centro do trilho.</translation>
    </message>
    <message>
        <source>Careful: left end of travel reached !!!</source>
        <translation>Cuidado : Fim de curso Esquerdo atingido !!!</translation>
    </message>
    <message>
        <source>Careful: right end of travel reached !!!</source>
        <translation>Cuidado : Fim de curso Direito atingido !!!</translation>
    </message>
    <message>
        <source>Maximum manual speed reached: lower the speed.</source>
        <translation>Velocidade máxima atingida: diminua a velocidade.</translation>
    </message>
    <message>
        <source>Program paused by the operator.</source>
        <translation>Programa pausado pelo operador.</translation>
    </message>
    <message>
        <source>Program resumed.</source>
        <translation>Programa retomado.</translation>
    </message>
    <message>
        <source>Program stopped by the operator.</source>
        <translation>Programa interrompido pelo operador.</translation>
    </message>
    <message>
        <source>Continue pressed.</source>
        <translation>Tecla Continua pressionada.</translation>
    </message>
    <message>
        <source>%1: Single block: press Continue for the next block.</source>
        <translation>%1: Bloco a bloco: pressione Continua para o próximo bloco.</translation>
    </message>
    <message>
        <source>Starting from block %1.</source>
        <translation>Execução a partir do bloco %1.</translation>
    </message>
    <message>
        <source>Alarm %2: %3</source>
        <translation>Alarme %2: %3</translation>
    </message>
    <message>
        <source>Alarm %2 acknowledged.</source>
        <translation>Alarme %2 reconhecido.</translation>
    </message>
    <message>
        <source>Emergency stop reset.</source>
        <translation>Emergência liberada.</translation>
    </message>
    <message>
        <source>POSITIONING</source>
        <translation>POSICIONANDO</translation>
    </message>
    <message>
        <source>WAITING</source>
        <translation>AGUARDANDO</translation>
    </message>
    <message>
        <source>Absolute coordinates</source>
        <translation>Coordenada absoluta</translation>
    </message>
    <message>
        <source>Incremental coordinates</source>
        <translation>Coordenada incremental</translation>
    </message>
    <message>
        <source>System zero changed</source>
        <translation>Zero do sistema mudado</translation>
    </message>
    <message>
        <source>Rail zero restored</source>
        <translation>Zera sistema trilho</translation>
    </message>
    <message>
        <source>Feed changed</source>
        <translation>Avanço mudado</translation>
    </message>
    <message>
        <source>Press Continue</source>
        <translation>Pressione Continua</translation>
    </message>
    <message>
        <source>Program jump</source>
        <translation>Desvio de programa</translation>
    </message>
    <message>
        <source>Program ended !</source>
        <translation>Programa terminado !</translation>
    </message>
    <message>
        <source>Compile error(s)!</source>
        <translation>Há erro(s) de compilação!</translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation>REFERENCIANDO</translation>
    </message>
    <message>
        <source>Ready</source>
        <translation>Pronto</translation>
    </message>
    <message>
        <source>PAUSED</source>
        <translation>PAUSADO</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Parado</translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation>ALARME</translation>
    </message>
    <message>
        <source>Left end of travel reached !</source>
        <translation>Fim de curso da esquerda atingido !</translation>
    </message>
    <message>
        <source>Right end of travel reached !</source>
        <translation>Fim de curso da direita atingido !</translation>
    </message>
    <message>
        <source>Following error: the platform did not follow the command</source>
        <translation>Erro de seguimento: a plataforma não seguiu o comando</translation>
    </message>
    <message>
        <source>Soft limit reached</source>
        <translation>Limite de curso programado atingido</translation>
    </message>
    <message>
        <source>The program has compile errors</source>
        <translation>O programa tem erros de compilação</translation>
    </message>
    <message>
        <source>Encoder fault: implausible counter readings</source>
        <translation>Falha do encoder: leituras impossíveis do contador</translation>
    </message>
    <message>
        <source>Amplifier fault</source>
        <translation>Falha do amplificador</translation>
    </message>
    <message>
        <source>Servo loop overrun: the watchdog stopped the drive</source>
        <translation>Atraso da malha de controle: o watchdog parou o acionamento</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Parada de emergência</translation>
    </message>
    <message>
        <source>Homing failed: centre switch not found</source>
        <translation>Falha ao ir para o centro: chave central não encontrada</translation>
    </message>
</context>
</TS>
