<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="pt_BR">
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
        <source>%1: Waiting %2 s.</source>
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
        <source>%1: Return to the rail&apos;s absolute zero.</source>
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
        <source>Homing: driving right until the centre mark or the right end switch.</source>
        <translation>Referência: indo para a direita até a marca central ou o fim de curso direito.</translation>
    </message>
    <message>
        <source>Homing: on the centre mark; leaving it to the right first.</source>
        <translation>Referência: sobre a marca central; saindo dela para a direita primeiro.</translation>
    </message>
    <message>
        <source>Homing: right end switch reached; driving left to the centre mark.</source>
        <translation>Referência: fim de curso direito atingido; indo para a esquerda até a marca central.</translation>
    </message>
    <message>
        <source>Homing: off the centre mark; driving left back to it.</source>
        <translation>Referência: fora da marca central; voltando para a esquerda até ela.</translation>
    </message>
    <message>
        <source>Homing: centre mark found; the counter is zeroed on it once the platform is still.</source>
        <translation>Referência: marca central encontrada; o contador é zerado nela quando a plataforma parar.</translation>
    </message>
    <message>
        <source>Homing: driving to x = 0, the rail centre.</source>
        <translation>Referência: indo para x = 0, o centro do trilho.</translation>
    </message>
    <message>
        <source>Homing stopped by the operator: the machine is not homed.</source>
        <translation>Referência interrompida pelo operador: a máquina não está referenciada.</translation>
    </message>
    <message>
        <source>Move stopped by the operator.</source>
        <translation>Movimento interrompido pelo operador.</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Parado</translation>
    </message>
    <message>
        <source>Homing stopped</source>
        <translation>Referência interrompida</translation>
    </message>
    <message>
        <source>Move stopped</source>
        <translation>Movimento interrompido</translation>
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
        <source>ALARM</source>
        <translation>ALARME</translation>
    </message>
    <message>
        <source>Left end of travel reached ! The end switch cut the drive. Acknowledge, then in Manual drive the platform to the right, back inside the limits.</source>
        <translation>Fim de curso da esquerda atingido ! A chave de fim de curso cortou o acionamento. Reconheça e, em Manual, leve a plataforma para a direita, de volta para dentro dos limites.</translation>
    </message>
    <message>
        <source>Right end of travel reached ! The end switch cut the drive. Acknowledge, then in Manual drive the platform to the left, back inside the limits.</source>
        <translation>Fim de curso da direita atingido ! A chave de fim de curso cortou o acionamento. Reconheça e, em Manual, leve a plataforma para a esquerda, de volta para dentro dos limites.</translation>
    </message>
    <message>
        <source>Following error: the platform did not follow the command (a jam, too heavy a load or a broken encoder cable) and the drive was cut. Free the rail, acknowledge, then home again with Automatic.</source>
        <translation>Erro de seguimento: a plataforma não seguiu o comando (travamento, carga pesada demais ou cabo do encoder rompido) e o acionamento foi cortado. Libere o trilho, reconheça e refaça o referenciamento com Automático.</translation>
    </message>
    <message>
        <source>Soft limit reached at x=%1 mm: the platform stopped there. Move it back the other way, inside the limits.</source>
        <translation>Limite de curso programado atingido em x=%1 mm: a plataforma parou ali. Leve-a de volta no sentido oposto, para dentro dos limites.</translation>
    </message>
    <message>
        <source>The program has compile errors: nothing moved. Correct the lines the diagnostics name, then run it again.</source>
        <translation>O programa tem erros de compilação: nada se moveu. Corrija as linhas apontadas nos diagnósticos e execute de novo.</translation>
    </message>
    <message>
        <source>Encoder fault: the counter gave implausible readings again and again, and the drive was cut. Check the encoder and its cable, acknowledge, then home again with Automatic.</source>
        <translation>Falha do encoder: o contador deu leituras impossíveis repetidas vezes e o acionamento foi cortado. Verifique o encoder e o cabo, reconheça e refaça o referenciamento com Automático.</translation>
    </message>
    <message>
        <source>Amplifier fault: the amplifier reported it is not ready and the drive was cut. Check its power, fuse and temperature, acknowledge, then home again with Automatic.</source>
        <translation>Falha do amplificador: o amplificador indicou que não está pronto e o acionamento foi cortado. Verifique a alimentação, o fusível e a temperatura dele, reconheça e refaça o referenciamento com Automático.</translation>
    </message>
    <message>
        <source>Control interrupted: the computer ran the position control too late, so the drive was cut for safety. Close other heavy programs, acknowledge, then home again with Automatic.</source>
        <translation>Controle interrompido: o computador executou o controle de posição com atraso, por isso o acionamento foi cortado por segurança. Feche outros programas pesados, reconheça e refaça o referenciamento com Automático.</translation>
    </message>
    <message>
        <source>Emergency stop: the drive was cut. Clear the cause, then press Reset E-stop.</source>
        <translation>Parada de emergência: o acionamento foi cortado. Elimine a causa e pressione Liberar emergência.</translation>
    </message>
    <message>
        <source>Homing failed: the centre switch was not found. Check the switch and its cable, acknowledge, then home again with Automatic.</source>
        <translation>Falha ao ir para o centro: a chave central não foi encontrada. Verifique a chave e o cabo, reconheça e refaça o referenciamento com Automático.</translation>
    </message>
    <message>
        <source>Soft limit: the platform would have passed the soft limit at x=%1 mm and was stopped before the end switch. Acknowledge, then move it back inside the limits.</source>
        <translation>Limite de software: a plataforma passaria do limite de software em x=%1 mm e foi parada antes do fim de curso. Reconheça e leve-a de volta para dentro dos limites.</translation>
    </message>
    <message>
        <source>Not in position: the platform did not settle on its target (%1 mm off). Check the payload and the gains, acknowledge, then run again.</source>
        <translation>Fora de posição: a plataforma não se assentou no alvo (a %1 mm). Verifique a carga e os ganhos, reconheça e execute de novo.</translation>
    </message>
    <message>
        <source>The program ended with the platform %1 mm from its last target, outside the final-position window. Check the payload and the gains, then run it again.</source>
        <translation>O programa terminou com a plataforma a %1 mm do último alvo, fora da janela de posição final. Verifique a carga e os ganhos e execute de novo.</translation>
    </message>
    <message>
        <source>The centre mark corrected the position by %1 mm: counts were lost or the cable slipped. The position is right again; if this repeats, check the encoder and its cable.</source>
        <translation>A marca central corrigiu a posição em %1 mm: houve perda de contagens ou o cabo escorregou. A posição está certa de novo; se isso se repetir, verifique o encoder e o cabo.</translation>
    </message>
    <message>
        <source>Motionless loop: the program repeats blocks that neither move nor wait. It is held: press Stop, or Continue to run it again.</source>
        <translation>Laço sem movimento: o programa repete blocos que não movem nem esperam. Ele está retido: pressione Parar, ou Continua para executá-lo de novo.</translation>
    </message>
    <message>
        <source>Encoder stalled: the drive ran %1 mm without a single count and was cut. Check the encoder and its cable, acknowledge, then home again.</source>
        <translation>Encoder parado: o acionamento comandou %1 mm sem uma única contagem e foi cortado. Verifique o encoder e o cabo, reconheça e refaça o referenciamento.</translation>
    </message>
    <message>
        <source>Over-current: a motor drew too much current at %1 % PWM and its drive was cut. Free the axis, acknowledge, then home again.</source>
        <translation>Sobrecorrente: um motor consumiu corrente demais a %1 % de PWM e o seu acionamento foi cortado. Libere o eixo, reconheça e depois faça a referência de novo.</translation>
    </message>
    <message>
        <source>Steps lost: homing found the origin %1 mm from where the counted steps put it. Lower the speed, acknowledge, then home again.</source>
        <translation>Passos perdidos: a referência achou a origem a %1 mm de onde os passos contados a punham. Reduza a velocidade, reconheça e depois faça a referência de novo.</translation>
    </message>
    <message>
        <source>Homing failed: the origin sensor was not found. Check the sensor and its cable, acknowledge, then home again.</source>
        <translation>Referência falhou: o sensor de origem não foi encontrado. Verifique o sensor e o seu cabo, reconheça e depois faça a referência de novo.</translation>
    </message>
    <message>
        <source>Link to the device lost: it did not answer, the line was too noisy, or the cable was pulled. The run is held: check the cable and the port, then press Continue to go on from the first point not acknowledged.</source>
        <translation>Ligação com o dispositivo perdida: ele não respondeu, a linha estava ruidosa demais ou o cabo foi desconectado. A execução está suspensa: verifique o cabo e a porta, depois pressione Continuar para seguir do primeiro ponto não confirmado.</translation>
    </message>
    <message>
        <source>Counts lost: the count differs by %1 mm from the travel the drive made, so the position is wrong and the drive was cut. Lower the speed or check the encoder and its counter card, acknowledge, then home again.</source>
        <translation>Contagens perdidas: a contagem difere em %1 mm do percurso que o acionamento fez, a posição está errada e o acionamento foi cortado. Reduza a velocidade ou verifique o encoder e a placa contadora, reconheça e refaça o referenciamento.</translation>
    </message>
    <message>
        <source>Runaway: seed 004&apos;s law drove an axis on, away from its set point (it acts on |e| with the direction fixed for the move, so an axis past its set point is driven further), and the drives were cut at the soft limit at %1 mm. Acknowledge, then move it back inside the limits.</source>
        <translation>Disparo: a lei da semente 004 levou um eixo adiante, para longe do seu ponto de ajuste (ela age sobre |e| com o sentido fixado para o movimento, então um eixo que passa do ponto de ajuste é levado ainda mais longe), e os acionamentos foram cortados no limite de software em %1 mm. Reconheça e leve-a de volta para dentro dos limites.</translation>
    </message>
    <message>
        <source>Move refused: seed 004&apos;s board would plan %1 samples for it and its arrays hold 480 (2.4 s). Its final-time formula counts forward moves only, so a return of more than 75 mm makes the count wrap to tens of thousands. Nothing was sent. Acknowledge, then give the move in shorter steps.</source>
        <translation>Movimento recusado: a placa do seed 004 planejaria %1 amostras para ele e seus vetores guardam 480 (2,4 s). Sua fórmula do tempo final só conta movimentos para a frente, e um retorno de mais de 75 mm faz a contagem dar a volta para dezenas de milhares. Nada foi enviado. Reconheça e dê o movimento em passos mais curtos.</translation>
    </message>
    <message>
        <source>%1: Travel to x=%2 y=%4 at maximum speed.</source>
        <translation>%1: Deslocamento para x=%2 y=%4 com velocidade máxima.</translation>
    </message>
    <message>
        <source>%1: Line to x=%2 y=%4 at %3% of maximum speed.</source>
        <translation>%1: Linha até x=%2 y=%4 com %3% da velocidade máxima.</translation>
    </message>
    <message>
        <source>Homing: going to the origin.</source>
        <translation>Referência: indo para a origem.</translation>
    </message>
    <message>
        <source>Homing done: at the origin.</source>
        <translation>Referência concluída: na origem.</translation>
    </message>
    <message>
        <source>Homing: the table does not move; its origin is where it stood at power-on.</source>
        <translation>Referência: a mesa não se move; a origem é onde ela estava ao ligar.</translation>
    </message>
    <message>
        <source>Homing done: the table stands at x=%2 y=%4 from its power-on origin.</source>
        <translation>Referência concluída: a mesa está em x=%2 y=%4 da origem ao ligar.</translation>
    </message>
    <message>
        <source>Program sent: every set point went to the board, which confirms nothing (seed 004&apos;s own firmware). The position shown is the planned one.</source>
        <translation>Programa enviado: todos os set points foram à placa, que não confirma nada (o firmware do próprio seed 004). A posição mostrada é a planejada.</translation>
    </message>
    <message>
        <source>%1: Return to the machine&apos;s absolute zero.</source>
        <translation>%1: Retorno ao zero absoluto da máquina.</translation>
    </message>
    <message>
        <source>Lower end of travel of the table reached ! An end switch cut the drives. Acknowledge, then in Manual drive the table back inside the limits.</source>
        <translation>Fim de curso inferior da mesa atingido ! Uma chave de fim de curso cortou os acionamentos. Reconheça e, em Manual, leve a mesa de volta para dentro dos limites.</translation>
    </message>
    <message>
        <source>Upper end of travel of the table reached ! An end switch cut the drives. Acknowledge, then in Manual drive the table back inside the limits.</source>
        <translation>Fim de curso superior da mesa atingido ! Uma chave de fim de curso cortou os acionamentos. Reconheça e, em Manual, leve a mesa de volta para dentro dos limites.</translation>
    </message>
    <message>
        <source>Following error: an axis of the table (x or y) was %1 mm behind the command (a jam, too heavy a load or a broken encoder cable) and both drives were cut. Free the table, acknowledge, then home again.</source>
        <translation>Erro de seguimento: um eixo da mesa (x ou y) ficou %1 mm atrás do comando (travamento, carga pesada demais ou cabo do encoder rompido) e os dois acionamentos foram cortados. Libere a mesa, reconheça e refaça o referenciamento.</translation>
    </message>
    <message>
        <source>Soft limit: the target is outside the table&apos;s travel, so the table stopped at its limit. Move it back the other way, inside the limits.</source>
        <translation>Limite de software: o alvo está fora do curso da mesa, e a mesa parou no limite. Leve-a de volta no sentido oposto, para dentro dos limites.</translation>
    </message>
    <message>
        <source>Homing failed: the table&apos;s origin was not found. Check its sensor and cable, acknowledge, then home again.</source>
        <translation>Falha no referenciamento: a origem da mesa não foi encontrada. Verifique o sensor e o cabo, reconheça e refaça o referenciamento.</translation>
    </message>
    <message>
        <source>Soft limit: the table would have passed the soft limit of its x or y axis at %1 mm and was stopped. Acknowledge, then move it back inside the limits.</source>
        <translation>Limite de software: a mesa passaria do limite de software do eixo x ou y em %1 mm e foi parada. Reconheça e leve-a de volta para dentro dos limites.</translation>
    </message>
    <message>
        <source>Not in position: the table did not settle on its target (%1 mm off on its x or y axis). Check the payload and the gains, acknowledge, then run again.</source>
        <translation>Fora de posição: a mesa não se assentou no alvo (a %1 mm no eixo x ou y). Verifique a carga e os ganhos, reconheça e execute de novo.</translation>
    </message>
    <message>
        <source>The program ended with the table %1 mm from its last target on its x or y axis, outside the final-position window. Check the payload and the gains, then run it again.</source>
        <translation>O programa terminou com a mesa a %1 mm do último alvo no eixo x ou y, fora da janela de posição final. Verifique a carga e os ganhos e execute de novo.</translation>
    </message>
    <message>
        <source>A reference mark corrected the table&apos;s position by %1 mm: counts were lost or a belt slipped. The position is right again; if this repeats, check the encoders and their cables.</source>
        <translation>Uma marca de referência corrigiu a posição da mesa em %1 mm: houve perda de contagens ou uma correia escorregou. A posição está certa de novo; se isso se repetir, verifique os encoders e os cabos.</translation>
    </message>
    <message>
        <source>Encoder stalled: a drive of the table (x or y axis) ran %1 mm without a single count and both drives were cut. Check the encoder and its cable, acknowledge, then home again.</source>
        <translation>Encoder parado: um acionamento da mesa (eixo x ou y) andou %1 mm sem uma única contagem e os acionamentos foram cortados. Verifique o encoder e o cabo, reconheça e refaça o referenciamento.</translation>
    </message>
    <message>
        <source>Over-current: a motor of the table (x or y axis) drew too much current at %1 % PWM and the drives were cut. Free the axis, acknowledge, then home again.</source>
        <translation>Sobrecorrente: um motor da mesa (eixo x ou y) puxou corrente demais a %1 % de PWM e os acionamentos foram cortados. Libere o eixo, reconheça e refaça o referenciamento.</translation>
    </message>
    <message>
        <source>Runaway: seed 004&apos;s law drove an axis of the table (x or y) on, away from its set point: it acts on |e| with the direction fixed for the move, so an axis that passes its set point is driven further. Both drives were cut at the soft limit at %1 mm. Acknowledge, then move the table back inside the limits (the seed-signed and engineered laws drive back instead).</source>
        <translation>Disparo: a lei da semente 004 levou um eixo da mesa (x ou y) adiante, para longe do seu ponto de ajuste: ela age sobre |e| com o sentido fixado para o movimento, então um eixo que passa do ponto de ajuste é levado ainda mais longe. Os dois acionamentos foram cortados no limite de software em %1 mm. Reconheça e leve a mesa de volta para dentro dos limites (as leis seed-signed e engineered a trazem de volta).</translation>
    </message>
</context>
<context>
    <name>Diagnostic</name>
    <message>
        <source>every line must start with n (found &apos;%2&apos;)</source>
        <translation>Erro: Toda linha deve iniciar com n.</translation>
    </message>
    <message>
        <source>wrong n sequence %1: must be greater than %3</source>
        <translation>Erro: Seqüência n errada %1</translation>
    </message>
    <message>
        <source>sequence number alone %1</source>
        <translation>Erro: Seqüência n sozinha %1</translation>
    </message>
    <message>
        <source>separating spaces required %1 (found &apos;%2&apos;)</source>
        <translation>Erro: Espaços para separação requeridos %1</translation>
    </message>
    <message>
        <source>there can be no more commands after %2 %1</source>
        <translation>Erro: Não pode haver mais comandos após %2 %1</translation>
    </message>
    <message>
        <source>g00 requires an x word %1</source>
        <translation>Erro: g00 requer comando x %1</translation>
    </message>
    <message>
        <source>g01 requires an x word %1</source>
        <translation>Erro: g01 requer comando x %1</translation>
    </message>
    <message>
        <source>g04 without x word (time) %1</source>
        <translation>Erro: g04 sem comando x (tempo) %1</translation>
    </message>
    <message>
        <source>g92 requires an x word %1</source>
        <translation>Erro: g92 requer comando x %1</translation>
    </message>
    <message>
        <source>m03 without x word (block) %1</source>
        <translation>Erro: m03 sem comando x (linha) %1</translation>
    </message>
    <message>
        <source>invalid value after g04 %1: the time %2 is negative</source>
        <translation>Erro: Caracter inválido após g04 %1</translation>
    </message>
    <message>
        <source>invalid value after m03 %1: the block %2 is negative</source>
        <translation>Erro: Caracter inválido após m03 %1</translation>
    </message>
    <message>
        <source>negative f command impossible %1 (%2)</source>
        <translation>Erro: Comando f negativo impossível %1</translation>
    </message>
    <message>
        <source>invalid g command %1 (%2)</source>
        <translation>Erro: Comando g inválido %1</translation>
    </message>
    <message>
        <source>invalid m command %1 (%2)</source>
        <translation>Erro: Comando m inválido %1</translation>
    </message>
    <message>
        <source>g01 or g00 not defined %1</source>
        <translation>Erro: g01 ou g00 não definidos %1</translation>
    </message>
    <message>
        <source>g01 needs f defined %1</source>
        <translation>Erro: g01 precisa de f definido %1</translation>
    </message>
    <message>
        <source>invalid character or g00 does not take f %1</source>
        <translation>Erro: Caracter inválido ou g00 não requer f %1</translation>
    </message>
    <message>
        <source>invalid character %1: &apos;%2&apos;</source>
        <translation>Erro: Caracter inválido %1 (&apos;%2&apos;)</translation>
    </message>
    <message>
        <source>invalid character %1: malformed number &apos;%2&apos;</source>
        <translation>Erro: Caracter inválido %1 (número malformado &apos;%2&apos;)</translation>
    </message>
    <message>
        <source>invalid character %1: &apos;%2&apos; must have exactly %3 digits</source>
        <translation>Erro: Caracter inválido %1 (&apos;%2&apos; deve ter %3 dígitos)</translation>
    </message>
    <message>
        <source>invalid character %1: comment not closed</source>
        <translation>Erro: Caracter inválido %1 (comentário não fechado)</translation>
    </message>
    <message>
        <source>invalid character %1: word &apos;%2&apos; repeated</source>
        <translation>Erro: Caracter inválido %1 (comando &apos;%2&apos; repetido)</translation>
    </message>
    <message>
        <source>invalid character %1: n must be the first word (&apos;%2&apos;)</source>
        <translation>Erro: Caracter inválido %1 (n deve ser o primeiro comando: &apos;%2&apos;)</translation>
    </message>
    <message>
        <source>invalid value after m03 %1: &apos;%2&apos; is not a block number</source>
        <translation>Erro: Caracter inválido após m03 %1 (&apos;%2&apos;)</translation>
    </message>
    <message>
        <source>invalid character %1: number &apos;%2&apos; longer than %3 digits</source>
        <translation>Erro: Caracter inválido %1 (número &apos;%2&apos; com mais de %3 dígitos)</translation>
    </message>
    <message>
        <source>program requires m02 (END) at the end</source>
        <translation>Erro: Programa requer m02 (END) no final</translation>
    </message>
    <message>
        <source>invalid GO TO %1: block n=%2 does not exist</source>
        <translation>Erro: GO TO Inválido %1 (bloco n=%2 não existe)</translation>
    </message>
    <message>
        <source>feed f%2 out of range %1: must be from %3 % to 100 %</source>
        <translation>Erro: Comando f fora da faixa %1 (f%2; deve ser de %3 % a 100 %)</translation>
    </message>
    <message>
        <source>target %2 mm %1 is beyond the soft limit %3 mm</source>
        <translation>Erro: Posição %2 mm %1 além do limite de curso %3 mm</translation>
    </message>
    <message>
        <source>axis %2 %1 does not exist on this machine</source>
        <translation>Erro: Eixo %2 %1 não existe nesta máquina</translation>
    </message>
    <message>
        <source>block number &apos;%2&apos; too large %1: at most %3</source>
        <translation>Erro: Número de bloco &apos;%2&apos; grande demais %1 (no máximo %3)</translation>
    </message>
    <message>
        <source>value &apos;%2&apos; too large %1: at most %3 in magnitude</source>
        <translation>Erro: Valor &apos;%2&apos; grande demais %1 (no máximo %3 em módulo)</translation>
    </message>
    <message>
        <source>in line n=%1</source>
        <translation>na linha %1</translation>
    </message>
    <message>
        <source>in block n=%1</source>
        <translation>no bloco n=%1</translation>
    </message>
    <message>
        <source>on line %1</source>
        <translation>na linha %1</translation>
    </message>
    <message>
        <source>Compilation completed successfully</source>
        <translation>Compilação completada com sucesso !</translation>
    </message>
    <message>
        <source>%1 compile error(s)</source>
        <translation>Há %1 erro(s) de compilação !</translation>
    </message>
    <message>
        <source>... and %1 more diagnostic(s) not listed</source>
        <translation>... e mais %1 diagnóstico(s) não listado(s)</translation>
    </message>
</context>
<context>
    <name>JournalNotice</name>
    <message>
        <source>The history is kept by another trilho (pid %1 on %2): this one writes %3.</source>
        <translation>O histórico é mantido por outro trilho (pid %1 em %2): este escreve %3.</translation>
    </message>
    <message>
        <source>The history is kept by another trilho: this one writes %1.</source>
        <translation>O histórico é mantido por outro trilho: este escreve %1.</translation>
    </message>
    <message>
        <source>The screens started %1 (%2) stopped without their end mark: they were killed, crashed or lost power.</source>
        <translation>As telas iniciadas em %1 (%2) pararam sem a marca de fim: foram encerradas à força, falharam ou ficaram sem energia.</translation>
    </message>
</context>
<context>
    <name>PreRunCheckText</name>
    <message>
        <source>during homing</source>
        <translation>durante a referência</translation>
    </message>
    <message>
        <source>on the way to the program&apos;s start</source>
        <translation>no caminho para o início do programa</translation>
    </message>
    <message>
        <source>at line %1</source>
        <translation>na linha %1</translation>
    </message>
    <message>
        <source>warning %1 (%2) %3</source>
        <translation>aviso %1 (%2) %3</translation>
    </message>
    <message>
        <source>alarm %1 (%2) %3</source>
        <translation>alarme %1 (%2) %3</translation>
    </message>
    <message>
        <source>no end within %1 s of machine time (a loop without end, a long dwell or a longer program)</source>
        <translation>sem fim em %1 s de tempo de máquina (um laço sem fim, uma espera longa ou um programa mais longo)</translation>
    </message>
    <message>
        <source>no end within %1 s of machine time: the feed override is at 0 %, nothing moves</source>
        <translation>sem fim em %1 s de tempo de máquina: a correção de avanço está em 0 %, nada se move</translation>
    </message>
    <message>
        <source>%1 goes %2 mm beyond its soft limits %3</source>
        <translation>%1 passa %2 mm além dos limites de software %3</translation>
    </message>
    <message>
        <source>Pre-run check: %1.</source>
        <translation>Verificação prévia: %1.</translation>
    </message>
    <message>
        <source>Pre-run check: cycle %1 s, worst following error %2 mm at line %3.</source>
        <translation>Verificação prévia: ciclo de %1 s, maior erro de seguimento %2 mm na linha %3.</translation>
    </message>
    <message>
        <source>Pre-run check: cycle %1 s, worst following error %2 mm.</source>
        <translation>Verificação prévia: ciclo de %1 s, maior erro de seguimento %2 mm.</translation>
    </message>
    <message>
        <source>Pre-run check: still running.</source>
        <translation>Verificação prévia: ainda em execução.</translation>
    </message>
    <message>
        <source>Pre-run check: not possible (see the details).</source>
        <translation>Verificação prévia: não foi possível (veja os detalhes).</translation>
    </message>
    <message>
        <source>The pre-run check of %1 could not run: %2</source>
        <translation>A verificação prévia de %1 não pôde ser feita: %2</translation>
    </message>
    <message>
        <source>Pre-run check of %1: ok.</source>
        <translation>Verificação prévia de %1: ok.</translation>
    </message>
    <message>
        <source>Pre-run check of %1: NOT OK: %2.</source>
        <translation>Verificação prévia de %1: NÃO OK: %2.</translation>
    </message>
    <message>
        <source>It ran on the simulated rail of the profile %1, in virtual time from homing, with the %2 (Kp %3, Ki %4, Kd %5) and the feed override at %6 %, as Cycle start runs it now.</source>
        <translation>Feita no trilho simulado do perfil %1, em tempo virtual a partir da referência, com a %2 (Kp %3, Ki %4, Kd %5) e a correção de avanço em %6 %, como o Início de ciclo o executa agora.</translation>
    </message>
    <message>
        <source>classic law</source>
        <translation>lei clássica</translation>
    </message>
    <message>
        <source>engineered law</source>
        <translation>lei moderna</translation>
    </message>
    <message>
        <source>It ran on the simulated machine of the profile %1, in virtual time from homing, with the feed override at %2 %, as Cycle start runs it now.</source>
        <translation>Feita na máquina simulada do perfil %1, em tempo virtual a partir da referência, com a correção de avanço em %2 %, como o Início de ciclo o executa agora.</translation>
    </message>
    <message>
        <source>An m00 is continued at once (the operator&apos;s wait is not in the cycle time); the Simulation dock&apos;s faults are not in it.</source>
        <translation>Um m00 é continuado de imediato (a espera do operador não entra no tempo de ciclo); as falhas do painel Simulação não entram nela.</translation>
    </message>
    <message>
        <source>Cycle time: unknown, still running after %1 s of machine time (the screens&apos; bound).</source>
        <translation>Tempo de ciclo: desconhecido, ainda em execução após %1 s de tempo de máquina (o limite das telas).</translation>
    </message>
    <message>
        <source>Cycle time: none, the program never started (homing did not end).</source>
        <translation>Tempo de ciclo: nenhum, o programa não começou (a referência não terminou).</translation>
    </message>
    <message>
        <source>Cycle time: %1 s from the program&apos;s start (after %2 s of homing).</source>
        <translation>Tempo de ciclo: %1 s desde o início do programa (após %2 s de referência).</translation>
    </message>
    <message>
        <source>Cycle time: %1 s from the program&apos;s start to where it stopped (after %2 s of homing).</source>
        <translation>Tempo de ciclo: %1 s desde o início do programa até onde parou (após %2 s de referência).</translation>
    </message>
    <message>
        <source>Envelope %1: %2 to %3 mm (soft limits %4 to %5 mm)</source>
        <translation>Envelope %1: %2 a %3 mm (limites de software %4 a %5 mm)</translation>
    </message>
    <message>
        <source>%1, OUTSIDE by %2 mm %3.</source>
        <translation>%1, FORA por %2 mm %3.</translation>
    </message>
    <message>
        <source>Worst following error: %1 mm on %2 %3, %4 s into the cycle.</source>
        <translation>Maior erro de seguimento: %1 mm em %2 %3, %4 s após o início do ciclo.</translation>
    </message>
    <message>
        <source>Worst following error: 0 mm.</source>
        <translation>Maior erro de seguimento: 0 mm.</translation>
    </message>
    <message>
        <source>Longest saturation of the drive: not modelled (the plotter&apos;s steppers have no drive level).</source>
        <translation>Maior saturação do acionamento: não modelada (os motores de passo do plotter não têm nível de acionamento).</translation>
    </message>
    <message>
        <source>Longest saturation of the drive: %1 s %2, %3 s into the cycle.</source>
        <translation>Maior saturação do acionamento: %1 s %2, %3 s após o início do ciclo.</translation>
    </message>
    <message>
        <source>Longest saturation of the drive: none.</source>
        <translation>Maior saturação do acionamento: nenhuma.</translation>
    </message>
    <message>
        <source>Alarms: none.</source>
        <translation>Alarmes: nenhum.</translation>
    </message>
    <message>
        <source>Warning %1 %2: %3</source>
        <translation>Aviso %1 %2: %3</translation>
    </message>
    <message>
        <source>Alarm %1 %2: %3</source>
        <translation>Alarme %1 %2: %3</translation>
    </message>
    <message>
        <source>... and %1 more.</source>
        <translation>... e mais %1.</translation>
    </message>
    <message>
        <source>m00: %1 stop(s) continued at once.</source>
        <translation>m00: %1 parada(s) continuada(s) de imediato.</translation>
    </message>
</context>
<context>
    <name>trilho</name>
    <message>
        <source>a verification move with the tuned gains was stopped by an alarm: %1</source>
        <translation>um movimento de verificação com os ganhos sintonizados foi parado por um alarme: %1</translation>
    </message>
    <message>
        <source>a verification move with the tuned gains did not end in position</source>
        <translation>um movimento de verificação com os ganhos sintonizados não terminou em posição</translation>
    </message>
    <message>
        <source>the experiment recorded too little</source>
        <translation>o experimento registrou poucos dados</translation>
    </message>
    <message>
        <source>the model fits the held-out run at %1 % on velocity, under %2 %</source>
        <translation>o modelo ajusta o ensaio de validação a %1 % na velocidade, abaixo de %2 %</translation>
    </message>
    <message>
        <source>the experiment needs %1 mm each side of its start inside the soft limits [%2, %3] mm; the axis is at %4 mm</source>
        <translation>o experimento precisa de %1 mm de cada lado do início dentro dos limites de software [%2, %3] mm; o eixo está em %4 mm</translation>
    </message>
    <message>
        <source>the table refused the drive (a limit, an alarm)</source>
        <translation>a mesa recusou o acionamento (um limite, um alarme)</translation>
    </message>
    <message>
        <source>the experiment was stopped by an alarm: %1</source>
        <translation>o experimento foi parado por um alarme: %1</translation>
    </message>
    <message>
        <source>the axis left the experiment&apos;s +-100 mm or its soft limits</source>
        <translation>o eixo saiu dos +-100 mm do experimento ou dos limites de software</translation>
    </message>
    <message>
        <source>the return to the start was stopped by an alarm: %1</source>
        <translation>o retorno ao início foi parado por um alarme: %1</translation>
    </message>
    <message>
        <source>the axis did not come back within one count of its start (%1 mm away)</source>
        <translation>o eixo não voltou a menos de uma contagem do início (ficou a %1 mm)</translation>
    </message>
    <message>
        <source>%1 %2 held to %3</source>
        <translation>%1 %2 limitado a %3</translation>
    </message>
    <message>
        <source>the servo refused the drive (a limit or an end switch)</source>
        <translation>o servo recusou o acionamento (um limite ou uma chave de fim de curso)</translation>
    </message>
    <message>
        <source>the platform left the experiment&apos;s +-100 mm</source>
        <translation>a plataforma saiu dos +-100 mm do experimento</translation>
    </message>
    <message>
        <source>the platform did not come back within one count of its start (%1 mm away)</source>
        <translation>a plataforma não voltou a menos de uma contagem do início (ficou a %1 mm)</translation>
    </message>
    <message>
        <source>the relay cycle left the experiment&apos;s +-100 mm</source>
        <translation>o ciclo do relé saiu dos +-100 mm do experimento</translation>
    </message>
    <message>
        <source>the relay did not oscillate (%1 switches in %2 s)</source>
        <translation>o relé não oscilou (%1 comutações em %2 s)</translation>
    </message>
    <message>
        <source>the relay cycle was too short to time</source>
        <translation>o ciclo do relé foi curto demais para ser medido</translation>
    </message>
    <message>
        <source>the relay cycle had no amplitude</source>
        <translation>o ciclo do relé não teve amplitude</translation>
    </message>
    <message>
        <source>no fault</source>
        <translation>sem falha</translation>
    </message>
    <message>
        <source>following error</source>
        <translation>erro de seguimento</translation>
    </message>
    <message>
        <source>left end switch</source>
        <translation>fim de curso esquerdo</translation>
    </message>
    <message>
        <source>right end switch</source>
        <translation>fim de curso direito</translation>
    </message>
    <message>
        <source>amplifier fault</source>
        <translation>falha do amplificador</translation>
    </message>
    <message>
        <source>hard stop</source>
        <translation>batente mecânico</translation>
    </message>
    <message>
        <source>soft limit</source>
        <translation>limite de software</translation>
    </message>
    <message>
        <source>encoder stalled</source>
        <translation>encoder parado</translation>
    </message>
    <message>
        <source>in-position timeout</source>
        <translation>tempo esgotado para chegar em posição</translation>
    </message>
    <message>
        <source>counts lost</source>
        <translation>contagens perdidas</translation>
    </message>
    <message>
        <source>late ticks</source>
        <translation>ticks atrasados</translation>
    </message>
    <message>
        <source>unknown fault</source>
        <translation>falha desconhecida</translation>
    </message>
</context>
<context>
    <name>trilho::SerialLine</name>
    <message>
        <source>serial port %1: %2 (was the device unplugged?)</source>
        <translation>porta serial %1: %2 (o dispositivo foi desconectado?)</translation>
    </message>
    <message>
        <source>cannot open serial port %1: %2</source>
        <translation>não foi possível abrir a porta serial %1: %2</translation>
    </message>
    <message>
        <source>cannot set %1 bit/s 8N1 on serial port %2: %3</source>
        <translation>não foi possível configurar %1 bit/s 8N1 na porta serial %2: %3</translation>
    </message>
</context>
<context>
    <name>trilho::ui::CalibrationDialog</name>
    <message>
        <source>Calibration of the table</source>
        <translation>Calibração da mesa</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>não medido</translation>
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
        <translation>Salvar perfil...</translation>
    </message>
    <message>
        <source>Run the board&apos;s calibration program, then press Start.</source>
        <translation>Rode o programa de calibração da placa e pressione Iniciar.</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>pulses</source>
        <translation>pulsos</translation>
    </message>
    <message>
        <source>displacement (mm)</source>
        <translation>deslocamento (mm)</translation>
    </message>
    <message>
        <source>Serial port:</source>
        <translation>Porta serial:</translation>
    </message>
    <message>
        <source>Bit rate:</source>
        <translation>Velocidade:</translation>
    </message>
    <message>
        <source>Axis:</source>
        <translation>Eixo:</translation>
    </message>
    <message>
        <source>Travel measured:</source>
        <translation>Deslocamento medido:</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>Receiving the counts on %1...</source>
        <translation>Recebendo as contagens em %1...</translation>
    </message>
    <message>
        <source>The stream is refused, nothing to save: %1. Press Start for a new run.</source>
        <translation>O fluxo foi recusado, nada a salvar: %1. Pressione Iniciar para uma nova execução.</translation>
    </message>
    <message>
        <source>Nothing to save: %1</source>
        <translation>Nada a salvar: %1</translation>
    </message>
    <message>
        <source>%1 counts, %2 pulses/s; the board stopped at about %3 pulses. %4 mm per pulse, %5 mm per turn (the profile has %6).</source>
        <translation>%1 contagens, %2 pulsos/s; a placa parou em cerca de %3 pulsos. %4 mm por pulso, %5 mm por volta (o perfil tem %6).</translation>
    </message>
    <message>
        <source>%1 counts, %2 pulses/s; the board stopped at about %3 pulses. Enter the travel measured for mm per pulse.</source>
        <translation>%1 contagens, %2 pulsos/s; a placa parou em cerca de %3 pulsos. Informe o deslocamento medido para obter mm por pulso.</translation>
    </message>
    <message>
        <source>Save profile</source>
        <translation>Salvar perfil</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Perfis de máquina (*.json)</translation>
    </message>
    <message>
        <source>Saved: %1</source>
        <translation>Salvo: %1</translation>
    </message>
</context>
<context>
    <name>trilho::ui::DcTablePanel</name>
    <message>
        <source>Set point</source>
        <translation>Ponto de ajuste</translation>
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
        <translation>X %1 mm enviado: envie Y para mover.</translation>
    </message>
    <message>
        <source>Y %1 mm sent: send X to move.</source>
        <translation>Y %1 mm enviado: envie X para mover.</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Executando</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Parado</translation>
    </message>
    <message>
        <source>Click to stop the table</source>
        <translation>Clique para parar a mesa</translation>
    </message>
    <message>
        <source>Click to start the table towards the set point</source>
        <translation>Clique para partir a mesa rumo ao ponto de ajuste</translation>
    </message>
    <message>
        <source>Entry number: raise it by one before a new set point (the operator&apos;s entries, seed 004); a lower number shows an earlier entry, to send it again</source>
        <translation>Número da entrada: aumente-o de um antes de um novo set point (as entradas do operador, seed 004); um número menor mostra uma entrada anterior, para enviá-la de novo</translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation>Porta serial</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Porta</translation>
    </message>
    <message>
        <source>Bit rate</source>
        <translation>Velocidade (bit/s)</translation>
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
        <translation>Defina o torque de carga e quando ele vem, depois Executar: usam-se o eixo, a lei, os ganhos, o período, a massa e a semente da janela. Experimente Ki 0, depois Ki 40.</translation>
    </message>
    <message>
        <source>Set the load and when it comes, then Run: the window&apos;s law, gains, period, mass and seed are used. Try Ki 0, then Ki 5.</source>
        <translation>Defina a carga e quando ela vem, depois Executar: usam-se a lei, os ganhos, o período, a massa e a semente da janela. Experimente Ki 0, depois Ki 5.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Not run:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Não executado:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Aborted:&lt;/b&gt; %1&lt;br&gt;</source>
        <translation>&lt;b&gt;Interrompido:&lt;/b&gt; %1&lt;br&gt;</translation>
    </message>
    <message>
        <source>No metrics: %1</source>
        <translation>Sem métricas: %1</translation>
    </message>
    <message>
        <source>Load %1 % of the stall torque on axis %2 at %3 s, Kp %4, Ki %5, Kff %6&lt;br&gt;</source>
        <translation>Carga de %1 % do torque de partida no eixo %2 em %3 s, Kp %4, Ki %5, Kff %6&lt;br&gt;</translation>
    </message>
    <message>
        <source>Load %1 N at %2 s, Kp %3, Ki %4, Kd %5&lt;br&gt;</source>
        <translation>Carga %1 N em %2 s, Kp %3, Ki %4, Kd %5&lt;br&gt;</translation>
    </message>
    <message>
        <source>Peak deviation before the stop: &lt;b&gt;%1 mm&lt;/b&gt;; no recovery and no steady state were measured</source>
        <translation>Desvio de pico antes da parada: &lt;b&gt;%1 mm&lt;/b&gt;; nem recuperação nem regime foram medidos</translation>
    </message>
    <message>
        <source>Peak deviation: &lt;b&gt;%1 mm&lt;/b&gt; at %2 s after the load&lt;br&gt;</source>
        <translation>Desvio de pico: &lt;b&gt;%1 mm&lt;/b&gt; %2 s após a carga&lt;br&gt;</translation>
    </message>
    <message>
        <source>Recovery time: &lt;b&gt;%1 s&lt;/b&gt; (back within %2 mm of where it was)&lt;br&gt;</source>
        <translation>Tempo de recuperação: &lt;b&gt;%1 s&lt;/b&gt; (de volta a menos de %2 mm de onde estava)&lt;br&gt;</translation>
    </message>
    <message>
        <source>Recovery time: &lt;b&gt;not reached&lt;/b&gt; (still more than %1 mm from where it was at the end)&lt;br&gt;</source>
        <translation>Tempo de recuperação: &lt;b&gt;não atingido&lt;/b&gt; (ainda a mais de %1 mm de onde estava, no fim)&lt;br&gt;</translation>
    </message>
    <message>
        <source>Steady deviation: &lt;b&gt;%1 mm&lt;/b&gt; (mean of the last %2 s)&lt;br&gt;</source>
        <translation>Desvio em regime: &lt;b&gt;%1 mm&lt;/b&gt; (média dos últimos %2 s)&lt;br&gt;</translation>
    </message>
    <message>
        <source>A PWM drive, no speed loop: with Ki 0 the loop rests about %1 mm off, where its drive less friction and a duty step meets the load, give or take friction&apos;s band</source>
        <translation>Acionamento PWM, sem malha de velocidade: com Ki 0 a malha para cerca de %1 mm fora, onde seu acionamento menos o atrito e um passo de ciclo encontra a carga, mais ou menos a faixa do atrito</translation>
    </message>
    <message>
        <source>A PWM drive, no speed loop: the motor&apos;s back EMF is its stiffness</source>
        <translation>Acionamento PWM, sem malha de velocidade: a força contraeletromotriz do motor é sua rigidez</translation>
    </message>
    <message>
        <source>Amplifier stiffness %1 N per mm/s: with Ki 0 the loop settles where Kp&apos;s drive gives back the speed the load adds, %2 mm</source>
        <translation>Rigidez do amplificador %1 N por mm/s: com Ki 0 a malha para onde o acionamento de Kp devolve a velocidade que a carga acrescenta, %2 mm</translation>
    </message>
    <message>
        <source>The amplifier is an ideal speed source: no load slows it</source>
        <translation>O amplificador é uma fonte de velocidade ideal: nenhuma carga o desacelera</translation>
    </message>
    <message>
        <source>Load torque on the axis</source>
        <translation>Torque de carga no eixo</translation>
    </message>
    <message>
        <source>Load on the platform</source>
        <translation>Carga na plataforma</translation>
    </message>
    <message>
        <source>Load comes at</source>
        <translation>A carga vem em</translation>
    </message>
    <message>
        <source>While</source>
        <translation>Durante</translation>
    </message>
    <message>
        <source>holding still</source>
        <translation>parado</translation>
    </message>
    <message>
        <source>moving (10 % of rapid)</source>
        <translation>movendo (10 % do rápido)</translation>
    </message>
    <message>
        <source>Run load test</source>
        <translation>Executar teste de carga</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>deviation (mm)</source>
        <translation>desvio (mm)</translation>
    </message>
    <message>
        <source>load (% of stall torque)</source>
        <translation>carga (% do torque de partida)</translation>
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
        <translation>Pasta dos programas</translation>
    </message>
    <message>
        <source>The address &apos;%1&apos; is not an IP address: write a numeric address such as 127.0.0.1 (this computer only), or 0.0.0.0 for every network interface.</source>
        <translation>O endereço &apos;%1&apos; não é um endereço IP: escreva um endereço numérico como 127.0.0.1 (só este computador) ou 0.0.0.0 para todas as interfaces de rede.</translation>
    </message>
    <message>
        <source>The port must be a whole number from 1 to 65535 (got &apos;%1&apos;); Modbus TCP&apos;s own is 502, which needs administrator rights: 1502 does not.</source>
        <translation>A porta deve ser um número inteiro de 1 a 65535 (recebido &apos;%1&apos;); a do Modbus TCP é 502, que exige direitos de administrador: 1502 não.</translation>
    </message>
    <message>
        <source>Modbus RTU needs the serial device, e.g. /dev/ttyUSB0 (or turn RTU off).</source>
        <translation>O Modbus RTU precisa do dispositivo serial, p. ex. /dev/ttyUSB0 (ou desligue o RTU).</translation>
    </message>
    <message>
        <source>The DNC settings could not be saved to %1 (a full disk or a folder that cannot be written): they hold until trilho closes.</source>
        <translation>As configurações do DNC não puderam ser salvas em %1 (disco cheio ou pasta sem permissão de escrita): valem até o trilho fechar.</translation>
    </message>
    <message>
        <source>Warning: %1 can be reached from other computers. Modbus has no password and no encryption: anyone on that network can read this machine and, while Remote is on, change its gains and run programs. Use 127.0.0.1 unless the cell&apos;s network is closed.</source>
        <translation>Atenção: %1 pode ser alcançado de outros computadores. O Modbus não tem senha nem criptografia: qualquer um nessa rede pode ler esta máquina e, com o Remoto ligado, mudar seus ganhos e executar programas. Use 127.0.0.1, a menos que a rede da célula seja fechada.</translation>
    </message>
    <message>
        <source>DNC: off</source>
        <translation>DNC: desligado</translation>
    </message>
    <message>
        <source>DNC link (Modbus)</source>
        <translation>Enlace DNC (Modbus)</translation>
    </message>
    <message>
        <source>Serve the DNC link (Modbus) for the cell&apos;s supervisor</source>
        <translation>Servir o enlace DNC (Modbus) para o supervisor da célula</translation>
    </message>
    <message>
        <source>Modbus TCP</source>
        <translation>Modbus TCP</translation>
    </message>
    <message>
        <source>Address:</source>
        <translation>Endereço:</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>Porta:</translation>
    </message>
    <message>
        <source>Modbus RTU on a serial line (8N1)</source>
        <translation>Modbus RTU numa linha serial (8N1)</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Dispositivo:</translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation>Baud:</translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation>Unidade (id):</translation>
    </message>
    <message>
        <source>Program library</source>
        <translation>Biblioteca</translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation>Pasta:</translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation>Procurar...</translation>
    </message>
    <message>
        <source>Reading is always allowed. Writes and commands need Remote (Options &gt; Remote, Ctrl+Shift+R), which is off at every start.</source>
        <translation>A leitura é sempre permitida. Escritas e comandos exigem o Remoto (Opções &gt; Remoto, Ctrl+Shift+R), que começa desligado a cada início.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::DncLink</name>
    <message>
        <source>Cannot listen on %1:%2: %3. Another program (another trilho?) may be using this port: choose another port or stop that program.</source>
        <translation>Não é possível escutar em %1:%2: %3. Outro programa (outro trilho?) pode estar usando esta porta: escolha outra porta ou feche esse programa.</translation>
    </message>
    <message>
        <source>DNC: cannot listen on %1:%2 (port taken?)</source>
        <translation>DNC: não escuta em %1:%2 (porta ocupada?)</translation>
    </message>
    <message>
        <source>Cannot open the serial device %1 for Modbus RTU: %2</source>
        <translation>Não é possível abrir o dispositivo serial %1 para Modbus RTU: %2</translation>
    </message>
    <message>
        <source>DNC: cannot open %1</source>
        <translation>DNC: não abre %1</translation>
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
        <translation>Remoto LIGADO</translation>
    </message>
    <message>
        <source>Remote off</source>
        <translation>Remoto desligado</translation>
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
        <translation>zero %1 mm</translation>
    </message>
    <message>
        <source>F %1 %</source>
        <translation>F %1 %</translation>
    </message>
    <message>
        <source>override %1 %</source>
        <translation>correção %1 %</translation>
    </message>
    <message>
        <source>classic law, %1 ms</source>
        <translation>lei clássica, %1 ms</translation>
    </message>
    <message>
        <source>engineered law, %1 ms</source>
        <translation>lei moderna, %1 ms</translation>
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
        <translation>Bloco %1 / %2</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ExecutionPanel</name>
    <message>
        <source>Alarms :</source>
        <translation>Alarmes :</translation>
    </message>
    <message>
        <source>Status :</source>
        <translation>Status :</translation>
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
        <translation>Dados Atuais :</translation>
    </message>
    <message>
        <source>Controller :</source>
        <translation>Controlador :</translation>
    </message>
    <message>
        <source>Loop :</source>
        <translation>Malha :</translation>
    </message>
    <message>
        <source>Program :</source>
        <translation>Programa :</translation>
    </message>
    <message>
        <source>Line :</source>
        <translation>Linha :</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continua</translation>
    </message>
    <message>
        <source>Left</source>
        <translation>Esquerda</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Direita</translation>
    </message>
    <message>
        <source>STOP</source>
        <translation>PÁRA</translation>
    </message>
    <message>
        <source>Position :</source>
        <translation>Posição :</translation>
    </message>
    <message>
        <source>Speed :</source>
        <translation>Velocidade :</translation>
    </message>
    <message>
        <source>Acceleration :</source>
        <translation>Aceleração :</translation>
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
        <translation>Integrativa :</translation>
    </message>
    <message>
        <source>Setpoint :</source>
        <translation>Setpoint :</translation>
    </message>
    <message>
        <source>Actual value :</source>
        <translation>Valor real :</translation>
    </message>
    <message>
        <source>Error :</source>
        <translation>Erro :</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>linha %1</translation>
    </message>
</context>
<context>
    <name>trilho::ui::GuideDialog</name>
    <message>
        <source>The guide is not installed here: %1 cannot be read.</source>
        <translation>O guia não está instalado aqui: %1 não pode ser lido.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::HistoryPanel</name>
    <message>
        <source>Export history</source>
        <translation>Exportar histórico</translation>
    </message>
    <message>
        <source>alarm</source>
        <translation>alarme</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>aviso</translation>
    </message>
    <message>
        <source>acknowledged</source>
        <translation>reconhecido</translation>
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
        <translation>retomada</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>parado</translation>
    </message>
    <message>
        <source>mode</source>
        <translation>modo</translation>
    </message>
    <message>
        <source>run start</source>
        <translation>início</translation>
    </message>
    <message>
        <source>run end</source>
        <translation>fim</translation>
    </message>
    <message>
        <source>override</source>
        <translation>correção</translation>
    </message>
    <message>
        <source>DNC write</source>
        <translation>Escrita DNC</translation>
    </message>
    <message>
        <source>start</source>
        <translation>início</translation>
    </message>
    <message>
        <source>stop</source>
        <translation>fim</translation>
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
        <translation>Reconhecer alarmes</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportar CSV</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Linha do tempo</translation>
    </message>
    <message>
        <source>The alarms, warnings, holds, overrides, mode changes and DNC writes of the history on a time axis</source>
        <translation>Os alarmes, avisos, esperas, correções de avanço, mudanças de modo e escritas DNC do histórico num eixo de tempo</translation>
    </message>
</context>
<context>
    <name>trilho::ui::JogPanel</name>
    <message>
        <source>Hold a key to jog</source>
        <translation>Segure uma tecla para mover</translation>
    </message>
    <message>
        <source>Hold to jog toward -X</source>
        <translation>Segure para mover para -X</translation>
    </message>
    <message>
        <source>Hold to jog toward +X</source>
        <translation>Segure para mover para +X</translation>
    </message>
    <message>
        <source>Jog speed %1 mm/s</source>
        <translation>Velocidade manual %1 mm/s</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Passo</translation>
    </message>
</context>
<context>
    <name>trilho::ui::KeysDialog</name>
    <message>
        <source>EMERGENCY STOP, in every window, menu and dialog</source>
        <translation>PARADA DE EMERGÊNCIA, em qualquer janela, menu ou diálogo</translation>
    </message>
    <message>
        <source>Stop (a controlled stop) when no menu, list or dialog is open; otherwise it only closes it</source>
        <translation>Parar (parada controlada) quando nenhum menu, lista ou diálogo está aberto; senão só o fecha</translation>
    </message>
    <message>
        <source>STOP: the manual PARA, or Stop in automatic (not in the editor)</source>
        <translation>PÁRA: o PÁRA manual, ou Parar em automático (não no editor)</translation>
    </message>
    <message>
        <source>Manual mode: left</source>
        <translation>Modo manual: esquerda</translation>
    </message>
    <message>
        <source>Manual mode: right</source>
        <translation>Modo manual: direita</translation>
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
        <translation>Ação</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MachineChoice</name>
    <message>
        <source>DC-motor XY table</source>
        <translation>Mesa XY com motores CC</translation>
    </message>
    <message>
        <source>Stepper XY plotter</source>
        <translation>Plotter XY com motores de passo</translation>
    </message>
    <message>
        <source>Robot rail (1996)</source>
        <translation>Trilho do robô (1996)</translation>
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
        <translation>%1 está em movimento. Trocar para %2 o para antes (parada controlada) e fecha a sua tela. Trocar?</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MachineLink</name>
    <message>
        <source>The simulated rail started again at x = 0 mm: the run that was going is lost; Execute homes it first.</source>
        <translation>O trilho simulado recomeçou em x = 0 mm: a execução em curso se perdeu; Executar faz a referência antes.</translation>
    </message>
    <message>
        <source>Command not taken: the servo thread&apos;s queue is full. Press again.</source>
        <translation>Comando não aceito: a fila do servo está cheia. Pressione de novo.</translation>
    </message>
    <message>
        <source>Program not started: the servo thread is still taking the one before it, or its queue is full. Press again.</source>
        <translation>Programa não iniciado: o servo ainda está recebendo o anterior, ou sua fila está cheia. Pressione de novo.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MainWindow</name>
    <message>
        <source>Start from a block runs in Automatic: choose Command &gt; Automatic first (it homes the rail).</source>
        <translation>Iniciar de um bloco funciona em Automático: escolha antes Comando &gt; Automático (ele referencia o trilho).</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>linha %1</translation>
    </message>
    <message>
        <source>Start from the selected block</source>
        <translation>Executar a partir do bloco selecionado</translation>
    </message>
    <message>
        <source>Start %1 from block %2? %3%4</source>
        <translation>Iniciar %1 a partir do bloco %2? %3%4</translation>
    </message>
    <message>
        <source>Its position is not known, so it homes first: %1 </source>
        <translation>A posição não é conhecida, então primeiro faz a referência: %1 </translation>
    </message>
    <message>
        <source>Didactic D.N.C. system for the automatic rail</source>
        <translation>Sistema D.N.C. didático para trilho automático</translation>
    </message>
    <message>
        <source>&amp;Select</source>
        <translation>&amp;Selecionar</translation>
    </message>
    <message>
        <source>&amp;Compile file</source>
        <translation>&amp;Compilar arquivo</translation>
    </message>
    <message>
        <source>&amp;Execute file</source>
        <translation>&amp;Executar arquivo</translation>
    </message>
    <message>
        <source>&amp;Theme</source>
        <translation>&amp;Tema</translation>
    </message>
    <message>
        <source>Classic (1996 colours)</source>
        <translation>Clássico (cores de 1996)</translation>
    </message>
    <message>
        <source>System</source>
        <translation>Sistema</translation>
    </message>
    <message>
        <source>Control &amp;law</source>
        <translation>&amp;Lei de controle</translation>
    </message>
    <message>
        <source>Classic (the 1996 difference equation)</source>
        <translation>Clássica (a equação de diferenças de 1996)</translation>
    </message>
    <message>
        <source>Engineered (profile, feed-forward)</source>
        <translation>Projetada (perfil, pré-alimentação)</translation>
    </message>
    <message>
        <source>G-code &amp;dialect</source>
        <translation>&amp;Dialeto de código G</translation>
    </message>
    <message>
        <source>Standard</source>
        <translation>Padrão</translation>
    </message>
    <message>
        <source>Classic (1996)</source>
        <translation>Clássico (1996)</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Rail</source>
        <translation>Trilho</translation>
    </message>
    <message>
        <source>EMERGENCY STOP LATCHED: the drive is off. Clear the cause, then Reset E-stop.</source>
        <translation>PARADA DE EMERGÊNCIA TRAVADA: o acionamento está desligado. Elimine a causa e depois Liberar emergência.</translation>
    </message>
    <message>
        <source>Set in the Simulation dock; Clear all there puts the rail right.</source>
        <translation>Definida no painel Simulação; Limpar tudo lá corrige o trilho.</translation>
    </message>
    <message>
        <source>File message</source>
        <translation>Mensagem de Arquivo</translation>
    </message>
    <message>
        <source>Select the file first !</source>
        <translation>Selecione o arquivo primeiro !</translation>
    </message>
    <message>
        <source>The program is loading: it compiles when it is loaded.</source>
        <translation>O programa está carregando: ele será compilado quando estiver carregado.</translation>
    </message>
    <message>
        <source>%1 changed on disk: reading it again.</source>
        <translation>%1 mudou no disco: lendo de novo.</translation>
    </message>
    <message>
        <source>The program changed while it compiled: nothing was run. Compile or execute it again.</source>
        <translation>O programa mudou durante a compilação: nada foi executado. Compile ou execute de novo.</translation>
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
        <translation>Compilação terminada !</translation>
    </message>
    <message>
        <source>Execute %1? %2%3 Then it runs the program.</source>
        <translation>Executar %1? %2%3 Depois executa o programa.</translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation>Início de ciclo</translation>
    </message>
    <message>
        <source> (the rail centre, where every program starts, as in the 1996 program)</source>
        <translation> (o centro do trilho, onde todo programa começa, como no programa de 1996)</translation>
    </message>
    <message>
        <source> (first programmed move to x = %1 mm)</source>
        <translation> (primeiro movimento programado para x = %1 mm)</translation>
    </message>
    <message>
        <source>It starts where homing leaves it, at x = %1 mm%2%3.</source>
        <translation>Começa onde a referência o deixa, em x = %1 mm%2%3.</translation>
    </message>
    <message>
        <source>It starts where it stands, at x = %1 mm%2%3.</source>
        <translation>Começa onde está, em x = %1 mm%2%3.</translation>
    </message>
    <message>
        <source>The rail moves at rapid speed from x = %1 mm to x = %2 mm%3%4.</source>
        <translation>O trilho move-se em velocidade rápida de x = %1 mm até x = %2 mm%3%4.</translation>
    </message>
    <message>
        <source>the rail drives right until a switch: the centre mark if it is left of the centre; otherwise the right end switch (about x = +%1 mm), then back left to the centre mark</source>
        <translation>o trilho anda para a direita até uma chave: a marca central se estiver à esquerda do centro; senão a chave de fim de curso direita (cerca de x = +%1 mm), e volta à esquerda até a marca central</translation>
    </message>
    <message>
        <source>the rail drives right from x = %1 mm to the centre mark</source>
        <translation>o trilho anda para a direita de x = %1 mm até a marca central</translation>
    </message>
    <message>
        <source>the rail drives right from x = %1 mm to the right end switch (about x = +%2 mm), then back left to the centre mark</source>
        <translation>o trilho anda para a direita de x = %1 mm até a chave de fim de curso direita (cerca de x = +%2 mm), e volta à esquerda até a marca central</translation>
    </message>
    <message>
        <source>%1, and stops at x = 0.</source>
        <translation>%1, e para em x = 0.</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automático</translation>
    </message>
    <message>
        <source>Automatic homes the rail first, as in 1996: %1 Home now?</source>
        <translation>O modo automático primeiro referencia o trilho, como em 1996: %1 Referenciar agora?</translation>
    </message>
    <message>
        <source>Home: stop the rail (or reset the E-stop, acknowledge the alarm) first.</source>
        <translation>Referenciar: pare o trilho (ou rearme a emergência, reconheça o alarme) antes.</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Referenciar</translation>
    </message>
    <message>
        <source>Home the rail? %1%2</source>
        <translation>Referenciar o trilho? %1%2</translation>
    </message>
    <message>
        <source> It then stays in Automatic.</source>
        <translation> Depois fica em Automático.</translation>
    </message>
    <message>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <source>There are compile error(s)!</source>
        <translation>Há erro(s) de compilação!</translation>
    </message>
    <message>
        <source>Late ticks: %1 (longest %2 ms)</source>
        <translation>Ciclos atrasados: %1 (maior %2 ms)</translation>
    </message>
    <message>
        <source>%1 status lines not shown</source>
        <translation>%1 linhas de status não mostradas</translation>
    </message>
    <message>
        <source>Manual</source>
        <translation>Manual</translation>
    </message>
    <message>
        <source>Automatic, ready</source>
        <translation>Automático, pronto</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Indo para o centro</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Executando</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>Aguardando</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pausado</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarme</translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation>Parada de emergência</translation>
    </message>
    <message>
        <source>The history could not be written: %1</source>
        <translation>O histórico não pôde ser gravado: %1</translation>
    </message>
    <message>
        <source>Emergency stop: clear the cause, then Reset E-stop.</source>
        <translation>Emergência: elimine a causa e então pressione Liberar emergência.</translation>
    </message>
    <message>
        <source>Alarm: read it in Alarms, then Acknowledge. Execute then homes the rail first if its position was lost.</source>
        <translation>Alarme: leia-o em Alarmes e Reconheça. Executar então faz o referenciamento antes, se a posição foi perdida.</translation>
    </message>
    <message>
        <source>Alarm: read it in Alarms, then Acknowledge.</source>
        <translation>Alarme: leia-o em Alarmes e Reconheça.</translation>
    </message>
    <message>
        <source>The rail&apos;s position is not known: Execute (or Automatic) homes it first.</source>
        <translation>A posição do trilho não é conhecida: Executar (ou Automático) faz o referenciamento antes.</translation>
    </message>
    <message>
        <source>Held: Resume goes on, Stop ends the program.</source>
        <translation>Retido: Retomar continua, Parar encerra o programa.</translation>
    </message>
    <message>
        <source>Cycle start runs in Automatic: choose Command &gt; Automatic first (it homes the rail).</source>
        <translation>O início de ciclo funciona em Automático: escolha antes Comando &gt; Automático (ele referencia o trilho).</translation>
    </message>
    <message>
        <source>Unsaved program</source>
        <translation>Programa não salvo</translation>
    </message>
    <message>
        <source>The program has unsaved changes. Save them before leaving?</source>
        <translation>O programa tem alterações não salvas. Salvar antes de sair?</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Salvar</translation>
    </message>
    <message>
        <source>Exit</source>
        <translation>Sair</translation>
    </message>
    <message>
        <source>The rail is moving (x = %1 mm, towards x = %2 mm). Exit stops it with an emergency stop. Exit now?</source>
        <translation>O trilho está em movimento (x = %1 mm, rumo a x = %2 mm). Sair o pára com uma parada de emergência. Sair agora?</translation>
    </message>
</context>
<context>
    <name>trilho::ui::MarginView</name>
    <message>
        <source>%1: no lost step up to %2 %3; the profile&apos;s %4 %3 has a margin of %5 (%6 %)</source>
        <translation>%1: nenhum passo perdido até %2 %3; os %4 %3 do perfil têm margem de %5 (%6 %)</translation>
    </message>
    <message>
        <source>%1: no lost step in the whole sweep (or as far as the travel lets a move reach its speed), up to %2 %3 (margin at least %4)</source>
        <translation>%1: nenhum passo perdido em toda a varredura (ou até onde o curso deixa um movimento atingir sua velocidade), até %2 %3 (margem de pelo menos %4)</translation>
    </message>
    <message>
        <source>Margin test refused: %1</source>
        <translation>Teste de margem recusado: %1</translation>
    </message>
    <message>
        <source>Axis %1: %2 trials out and back, %3 s of machine time (simulation only: the board reports no step count; on the machine, check a pen mark at the start).</source>
        <translation>Eixo %1: %2 ensaios de ida e volta, %3 s de tempo de máquina (só simulação: a placa não informa a contagem de passos; na máquina, confira uma marca de caneta no início).</translation>
    </message>
    <message>
        <source>Speed at the profile&apos;s acceleration</source>
        <translation>Velocidade na aceleração do perfil</translation>
    </message>
    <message>
        <source>Acceleration at the profile&apos;s speed</source>
        <translation>Aceleração na velocidade do perfil</translation>
    </message>
    <message>
        <source>no loss</source>
        <translation>sem perda</translation>
    </message>
    <message>
        <source>lost steps</source>
        <translation>passos perdidos</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>velocidade</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>aceleração</translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation>Varredura</translation>
    </message>
    <message>
        <source>Speed (mm/s)</source>
        <translation>Velocidade (mm/s)</translation>
    </message>
    <message>
        <source>Acceleration (mm/s²)</source>
        <translation>Aceleração (mm/s²)</translation>
    </message>
    <message>
        <source>Move (mm)</source>
        <translation>Movimento (mm)</translation>
    </message>
    <message>
        <source>Lost steps</source>
        <translation>Passos perdidos</translation>
    </message>
    <message>
        <source>Return error (steps)</source>
        <translation>Erro no retorno (passos)</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Resultado</translation>
    </message>
    <message>
        <source>The plotter has no encoder: its test is the margin of its speed and acceleration against lost steps. Choose the axis and press Run margin test.</source>
        <translation>O plotter não tem encoder: seu teste é a margem da velocidade e da aceleração contra passos perdidos. Escolha o eixo e pressione Executar teste de margem.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ModelView</name>
    <message>
        <source>Identify or autotune the rail to see its model, its fit and its Bode plot.</source>
        <translation>Identifique o trilho ou faça a sintonia automática para ver o modelo, o ajuste e o diagrama de Bode.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Identified model&lt;/b&gt; (G = K / (s (tau s + 1)), acceleration limited, Coulomb friction)</source>
        <translation>&lt;b&gt;Modelo identificado&lt;/b&gt; (G = K / (s (tau s + 1)), aceleração limitada, atrito de Coulomb)</translation>
    </message>
    <message>
        <source>speed gain K = %1 mm/s per code</source>
        <translation>ganho de velocidade K = %1 mm/s por código</translation>
    </message>
    <message>
        <source>time constant tau = %1 ms</source>
        <translation>constante de tempo tau = %1 ms</translation>
    </message>
    <message>
        <source>acceleration limit = %1 mm/s2 (mass %2 kg)</source>
        <translation>limite de aceleração = %1 mm/s2 (massa %2 kg)</translation>
    </message>
    <message>
        <source>Coulomb friction = %1 mm/s2 (%2 N)</source>
        <translation>atrito de Coulomb = %1 mm/s2 (%2 N)</translation>
    </message>
    <message>
        <source>fit on held-out velocity (NRMSE) = &lt;b&gt;%1 %&lt;/b&gt;; on the fitted part %2 %; on position %3 % (flattering: position integrates)</source>
        <translation>ajuste na velocidade de validação (NRMSE) = &lt;b&gt;%1 %&lt;/b&gt;; na parte ajustada %2 %; na posição %3 % (otimista: a posição integra)</translation>
    </message>
    <message>
        <source>experiment: %1 s of machine time, at most %2 mm from the start, back within %3 counts</source>
        <translation>experimento: %1 s de tempo de máquina, no máximo a %2 mm do início, de volta a menos de %3 contagens</translation>
    </message>
    <message>
        <source>Model refused: %1</source>
        <translation>Modelo recusado: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Margins&lt;/b&gt;: gain %1 dB at %2 rad/s; phase %3 deg at %4 rad/s</source>
        <translation>&lt;b&gt;Margens&lt;/b&gt;: ganho %1 dB em %2 rad/s; fase %3 deg em %4 rad/s</translation>
    </message>
    <message>
        <source>infinite</source>
        <translation>infinito</translation>
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
        <translation>frequência (rad/s)</translation>
    </message>
    <message>
        <source>Open loop with the profile&apos;s engineered gains (Kp %1, Ki %2, Kd %3):</source>
        <translation>Malha aberta com os ganhos da lei moderna do perfil (Kp %1, Ki %2, Kd %3):</translation>
    </message>
    <message>
        <source>&lt;b&gt;Design&lt;/b&gt; (SIMC, closed-loop time constant %1 ms, delay %2 ms): Kp %3, Ki %4, Kd %5; planning acceleration %6 mm/s2</source>
        <translation>&lt;b&gt;Projeto&lt;/b&gt; (SIMC, constante de tempo em malha fechada %1 ms, atraso %2 ms): Kp %3, Ki %4, Kd %5; aceleração de planejamento %6 mm/s2</translation>
    </message>
    <message>
        <source>Prediction (on the model, before applying) against measurement</source>
        <translation>Previsão (no modelo, antes de aplicar) contra medição</translation>
    </message>
    <message>
        <source>overshoot predicted (counts)</source>
        <translation>sobressinal previsto (contagens)</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message>
        <source>settling +-1 count predicted (ms)</source>
        <translation>acomodação +-1 contagem prevista (ms)</translation>
    </message>
    <message>
        <source>%1 mm step</source>
        <translation>degrau de %1 mm</translation>
    </message>
    <message>
        <source>%1 mm move</source>
        <translation>movimento de %1 mm</translation>
    </message>
    <message>
        <source>Machine time of the whole autotune: %1 s</source>
        <translation>Tempo de máquina de toda a sintonia automática: %1 s</translation>
    </message>
    <message>
        <source>&lt;b&gt;Autotune passed&lt;/b&gt;: the tuned gains are in the step test&apos;s boxes; Save tuned profile... keeps them in a profile.</source>
        <translation>&lt;b&gt;Sintonia automática aprovada&lt;/b&gt;: os ganhos sintonizados estão nos campos do teste de degrau; Salvar perfil sintonizado... os guarda num perfil.</translation>
    </message>
    <message>
        <source>Autotune failed: %1</source>
        <translation>Sintonia automática falhou: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Identified model&lt;/b&gt; (PWM-driven motor: G = K / (s (tau s + 1)), Coulomb friction)</source>
        <translation>&lt;b&gt;Modelo identificado&lt;/b&gt; (motor acionado por PWM: G = K / (s (tau s + 1)), atrito de Coulomb)</translation>
    </message>
    <message>
        <source>speed gain K = %1 mm/s per PWM %</source>
        <translation>ganho de velocidade K = %1 mm/s por % de PWM</translation>
    </message>
    <message>
        <source>time constant tau = %1 ms (inertia x%2 of the profile&apos;s)</source>
        <translation>constante de tempo tau = %1 ms (inércia x%2 da do perfil)</translation>
    </message>
    <message>
        <source>Coulomb friction = %1 % PWM</source>
        <translation>atrito de Coulomb = %1 % de PWM</translation>
    </message>
    <message>
        <source>acceleration limit = %1 mm/s2 (the over-current trip)</source>
        <translation>limite de aceleração = %1 mm/s2 (o disparo de sobrecorrente)</translation>
    </message>
    <message>
        <source>Open loop with the profile&apos;s engineered gains (Kp %1, Ki %2, Kff %3):</source>
        <translation>Malha aberta com os ganhos da lei de engenharia do perfil (Kp %1, Ki %2, Kff %3):</translation>
    </message>
    <message>
        <source>&lt;b&gt;Design&lt;/b&gt; (SIMC PI, closed-loop time constant %1 ms, effective delay %2 ms): Kp %3, Ki %4, Kff %5; planning acceleration %6 mm/s2</source>
        <translation>&lt;b&gt;Projeto&lt;/b&gt; (PI SIMC, constante de tempo em malha fechada %1 ms, atraso efetivo %2 ms): Kp %3, Ki %4, Kff %5; aceleração de planejamento %6 mm/s2</translation>
    </message>
    <message>
        <source>&lt;b&gt;Relay experiment&lt;/b&gt; (Astrom-Hagglund): a relay of +-%1 codes on the position error, hysteresis %2 counts</source>
        <translation>&lt;b&gt;Experimento do relé&lt;/b&gt; (Astrom-Hagglund): um relé de +-%1 códigos sobre o erro de posição, histerese de %2 contagens</translation>
    </message>
    <message>
        <source>limit cycle: amplitude a = %1 mm, period Tu = %2 ms</source>
        <translation>ciclo limite: amplitude a = %1 mm, período Tu = %2 ms</translation>
    </message>
    <message>
        <source>ultimate gain Ku = 4 d / (pi a) = %1 code/mm</source>
        <translation>ganho crítico Ku = 4 d / (pi a) = %1 código/mm</translation>
    </message>
    <message>
        <source>Relay experiment failed: %1</source>
        <translation>O experimento do relé falhou: %1</translation>
    </message>
    <message>
        <source>experiment: %1 s of machine time, back within %2 counts</source>
        <translation>experimento: %1 s de tempo de máquina, de volta a %2 contagens</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>não atingido</translation>
    </message>
    <message>
        <source>Ziegler-Nichols (relay)</source>
        <translation>Ziegler-Nichols (relé)</translation>
    </message>
    <message>
        <source>model-based (SIMC)</source>
        <translation>baseado no modelo (SIMC)</translation>
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
        <translation>degrau de 10 mm: sobressinal (%)</translation>
    </message>
    <message>
        <source>rise time 10-90 % (s)</source>
        <translation>tempo de subida 10-90 % (s)</translation>
    </message>
    <message>
        <source>settling to +-1 count (s)</source>
        <translation>acomodação a +-1 contagem (s)</translation>
    </message>
    <message>
        <source>steady-state error (counts)</source>
        <translation>erro em regime (contagens)</translation>
    </message>
    <message>
        <source>no</source>
        <translation>não</translation>
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
        <translation>Um experimento para ensinar, não a sintonia padrão: nesta planta a quantização do DAC, o atrito e o limite de corrente definem o ciclo limite tanto quanto a dinâmica.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::OperatorFrame</name>
    <message>
        <source>Operator&apos;s guide</source>
        <translation>Guia do operador</translation>
    </message>
    <message>
        <source>Teaching guide</source>
        <translation>Guia de ensino</translation>
    </message>
    <message>
        <source>About trilho</source>
        <translation>Sobre o trilho</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;trilho %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Numerical control for the robot rail of the 1996 manufacturing cell (University of São Paulo) and two XY tables, simulated by default.&lt;/p&gt;&lt;p&gt;Guides: %2&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;trilho %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Comando numérico para o trilho do robô da célula de manufatura de 1996 (Universidade de São Paulo) e duas mesas XY, simuladas por padrão.&lt;/p&gt;&lt;p&gt;Guias: %2&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Settings not saved: cannot write %1 (a full disk or a folder that cannot be written). The old settings are kept; this change holds until trilho closes.</source>
        <translation>Configurações não salvas: não é possível gravar %1 (disco cheio ou pasta sem permissão de escrita). As configurações antigas são mantidas; esta mudança vale até o trilho fechar.</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Máquina</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <source>&amp;Machine...</source>
        <translation>&amp;Máquina...</translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation>Sai&amp;r</translation>
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
        <translation>Referenciar (Ctrl+Home)</translation>
    </message>
    <message>
        <source>O&amp;ptions</source>
        <translation>O&amp;pções</translation>
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
        <translation>Permite ao supervisor da célula escrever e comandar pelo enlace DNC (%1). Desligado a cada início.</translation>
    </message>
    <message>
        <source>&amp;Windows</source>
        <translation>&amp;Janelas</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Restaurar disposição</translation>
    </message>
    <message>
        <source>Tuning &amp;workbench...</source>
        <translation>&amp;Bancada de sintonia...</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Aj&amp;uda</translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation>&amp;Teclas</translation>
    </message>
    <message>
        <source>&amp;Operator&apos;s guide</source>
        <translation>Guia do &amp;operador</translation>
    </message>
    <message>
        <source>&amp;Teaching guide</source>
        <translation>Guia de &amp;ensino</translation>
    </message>
    <message>
        <source>&amp;About trilho</source>
        <translation>&amp;Sobre o trilho</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Histórico</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulação</translation>
    </message>
    <message>
        <source>Program library</source>
        <translation>Biblioteca</translation>
    </message>
    <message>
        <source>Safety</source>
        <translation>Segurança</translation>
    </message>
    <message>
        <source>Reset E-stop</source>
        <translation>Liberar emergência</translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation>Reconhecer</translation>
    </message>
    <message>
        <source>E-STOP LATCHED</source>
        <translation>EMERGÊNCIA ACIONADA</translation>
    </message>
    <message>
        <source>E-STOP (Pause, F1)</source>
        <translation>EMERGÊNCIA (Pause, F1)</translation>
    </message>
    <message>
        <source>Simulated fault armed: %1</source>
        <translation>Falha simulada ativa: %1</translation>
    </message>
    <message>
        <source>Feed override %1 %</source>
        <translation>Correção de avanço %1 %</translation>
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
        <translation>Janela de tempo</translation>
    </message>
    <message>
        <source>setpoint</source>
        <translation>setpoint</translation>
    </message>
    <message>
        <source>position</source>
        <translation>posição</translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation>posição (mm)</translation>
    </message>
    <message>
        <source>error (mm)</source>
        <translation>erro (mm)</translation>
    </message>
    <message>
        <source>DAC</source>
        <translation>DAC</translation>
    </message>
    <message>
        <source>following error (mm)</source>
        <translation>erro de seguimento (mm)</translation>
    </message>
    <message>
        <source>drive (DAC code)</source>
        <translation>acionamento (código DAC)</translation>
    </message>
    <message>
        <source>cannot write &apos;%1&apos;: the image could not be encoded</source>
        <translation>não é possível gravar &apos;%1&apos;: a imagem não pôde ser codificada</translation>
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
        <translation>Recebido: %1</translation>
    </message>
    <message>
        <source>Time: %1 s</source>
        <translation>Tempo: %1 s</translation>
    </message>
    <message>
        <source>Communication log</source>
        <translation>Log de comunicação</translation>
    </message>
    <message>
        <source>Clear log</source>
        <translation>Limpar log</translation>
    </message>
    <message>
        <source>No object sent yet</source>
        <translation>Nenhum objeto enviado ainda</translation>
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
        <translation>Origem</translation>
    </message>
    <message>
        <source>Jog up (+y)</source>
        <translation>Mover para cima (+y)</translation>
    </message>
    <message>
        <source>Jog down (-y)</source>
        <translation>Mover para baixo (-y)</translation>
    </message>
    <message>
        <source>Jog left (-x)</source>
        <translation>Mover para a esquerda (-x)</translation>
    </message>
    <message>
        <source>Jog right (+x)</source>
        <translation>Mover para a direita (+x)</translation>
    </message>
    <message>
        <source>Jog step</source>
        <translation>Passo do movimento</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidade</translation>
    </message>
    <message>
        <source> steps/s</source>
        <translation> passos/s</translation>
    </message>
    <message>
        <source>Object: %1 points (at most 300 per object)</source>
        <translation>Objeto: %1 pontos (no máximo 300 por objeto)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PolesView</name>
    <message>
        <source>Seed 004&apos;s law as written has no poles: it drives by |e| with the move&apos;s direction bit fixed, not a linear loop (past the target it drives on). Its signed reading, with the same b0 and b1, has them.</source>
        <translation>A lei do seed 004 como escrita não tem polos: aciona por |e| com o bit de direção do movimento fixo, não é uma malha linear (passado o alvo, segue acionando). Sua leitura com sinal, com os mesmos b0 e b1, tem.</translation>
    </message>
    <message>
        <source>Identify the plant to see the closed loop&apos;s poles and zeros for the gains in the boxes.</source>
        <translation>Identifique a planta para ver os polos e zeros da malha fechada com os ganhos das caixas.</translation>
    </message>
    <message>
        <source>engineered</source>
        <translation>moderna</translation>
    </message>
    <message>
        <source>seed 004 (signed error)</source>
        <translation>seed 004 (erro com sinal)</translation>
    </message>
    <message>
        <source>1996</source>
        <translation>1996</translation>
    </message>
    <message>
        <source>&lt;b&gt;Closed loop at T = %1 ms&lt;/b&gt; (%2 law, %3; model K %4 %5, tau %6 ms)</source>
        <translation>&lt;b&gt;Malha fechada a T = %1 ms&lt;/b&gt; (lei %2, %3; modelo K %4 %5, tau %6 ms)</translation>
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
        <translation>zeros (o):</translation>
    </message>
    <message>
        <source>largest |z| %1: stable, inside the unit circle.</source>
        <translation>maior |z| %1: estável, dentro do círculo unitário.</translation>
    </message>
    <message>
        <source>&lt;font color=&quot;#c00000&quot;&gt;&lt;b&gt;largest |z| %1: unstable, on or outside the unit circle.&lt;/b&gt;&lt;/font&gt;</source>
        <translation>&lt;font color=&quot;#c00000&quot;&gt;&lt;b&gt;maior |z| %1: instável, sobre ou fora do círculo unitário.&lt;/b&gt;&lt;/font&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dominant pair&lt;/b&gt; %1: damping %2, natural frequency %3 rad/s (z = exp(sT), s = ln z / T)</source>
        <translation>&lt;b&gt;Par dominante&lt;/b&gt; %1: amortecimento %2, frequência natural %3 rad/s (z = exp(sT), s = ln z / T)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dominant pole&lt;/b&gt; %1: damping %2, natural frequency %3 rad/s (z = exp(sT), s = ln z / T)</source>
        <translation>&lt;b&gt;Polo dominante&lt;/b&gt; %1: amortecimento %2, frequência natural %3 rad/s (z = exp(sT), s = ln z / T)</translation>
    </message>
    <message>
        <source>The loop leaves the unit circle above %1 %2.</source>
        <translation>A malha sai do círculo unitário acima de %1 %2.</translation>
    </message>
    <message>
        <source>... and below %1 %2.</source>
        <translation>... e abaixo de %1 %2.</translation>
    </message>
    <message>
        <source>Root locus (grey): %1 from %2 to %3; the poles for the gains in the boxes are the crosses.</source>
        <translation>Lugar das raízes (cinza): %1 de %2 a %3; os polos dos ganhos das caixas são as cruzes.</translation>
    </message>
    <message>
        <source>unit circle</source>
        <translation>círculo unitário</translation>
    </message>
    <message>
        <source>root locus (Kp)</source>
        <translation>lugar das raízes (Kp)</translation>
    </message>
    <message>
        <source>zeros</source>
        <translation>zeros</translation>
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
        <translation>linha %1: esperados dois números, x e y em mm (veio &apos;%2&apos;)</translation>
    </message>
    <message>
        <source>a polygon needs at least three points (got %1)</source>
        <translation>um polígono precisa de pelo menos três pontos (vieram %1)</translation>
    </message>
    <message>
        <source>Polygon from points</source>
        <translation>Polígono por pontos</translation>
    </message>
    <message>
        <source>One point a line: x y in mm (e.g. 20 20)</source>
        <translation>Um ponto por linha: x y em mm (ex.: 20 20)</translation>
    </message>
    <message>
        <source>Plot</source>
        <translation>Plotar</translation>
    </message>
    <message>
        <source>Vertices (x y, mm):</source>
        <translation>Vértices (x y, mm):</translation>
    </message>
    <message>
        <source>Feed:</source>
        <translation>Avanço:</translation>
    </message>
    <message>
        <source>The polygon is closed back to its first point.</source>
        <translation>O polígono é fechado de volta ao primeiro ponto.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::PredictionView</name>
    <message>
        <source>Seed 004&apos;s law as written is not a linear loop (|e| with the move&apos;s direction bit): no prediction. Run its step instead.</source>
        <translation>A lei do seed 004 como escrita não é uma malha linear (|e| com o bit de direção do movimento): não há previsão. Execute o seu degrau.</translation>
    </message>
    <message>
        <source>Identify the plant to see the step the model predicts for the gains in the boxes; drag a gain&apos;s slider to move it.</source>
        <translation>Identifique a planta para ver o degrau que o modelo prevê para os ganhos nas caixas; arraste o controle deslizante de um ganho para movê-lo.</translation>
    </message>
    <message>
        <source>No prediction: the period or the model is not valid.</source>
        <translation>Sem previsão: o período ou o modelo não é válido.</translation>
    </message>
    <message>
        <source>Step of %1 mm predicted on the model (linear: no clamp, no feed-forward):</source>
        <translation>Degrau de %1 mm previsto no modelo (linear: sem limitação, sem feed-forward):</translation>
    </message>
    <message>
        <source>the loop is unstable, the response grows.</source>
        <translation>a malha é instável, a resposta cresce.</translation>
    </message>
    <message>
        <source>overshoot %1 %, not settled within %2 s.</source>
        <translation>sobressinal %1 %, não acomodado em %2 s.</translation>
    </message>
    <message>
        <source>overshoot %1 %, settling (2 %) %2 s.</source>
        <translation>sobressinal %1 %, acomodação (2 %) %2 s.</translation>
    </message>
    <message>
        <source>Grey: where the drag started.</source>
        <translation>Cinza: onde o arrasto começou.</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation>posição (mm)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ProgramLibraryPanel</name>
    <message>
        <source>Folder: %1</source>
        <translation>Pasta: %1</translation>
    </message>
    <message>
        <source>Folder: %1 (not created yet)</source>
        <translation>Pasta: %1 (ainda não criada)</translation>
    </message>
    <message>
        <source>%1 bytes, no comment</source>
        <translation>%1 bytes, sem comentário</translation>
    </message>
    <message>
        <source>Not served: %1</source>
        <translation>Não servido: %1</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>Nº</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Arquivo</translation>
    </message>
    <message>
        <source>Comment or size</source>
        <translation>Comentário ou tamanho</translation>
    </message>
    <message>
        <source>Modified</source>
        <translation>Modificado</translation>
    </message>
    <message>
        <source>Open in the editor</source>
        <translation>Abrir no editor</translation>
    </message>
</context>
<context>
    <name>trilho::ui::ProgramPanel</name>
    <message>
        <source>Save</source>
        <translation>Salvar</translation>
    </message>
    <message>
        <source>Start from the selected block</source>
        <translation>Executar a partir do bloco selecionado</translation>
    </message>
    <message>
        <source>A program this large is shown read-only: edit it in a text editor</source>
        <translation>Um programa deste tamanho é mostrado só para leitura: edite-o num editor de texto</translation>
    </message>
    <message>
        <source>Saves atomically: a crash never leaves half a file</source>
        <translation>Salva de forma atômica: uma falha nunca deixa meio arquivo</translation>
    </message>
    <message>
        <source>%1 lines: too large to edit here, shown read-only. Click a line to select its block.</source>
        <translation>%1 linhas: grande demais para editar aqui, mostrado só para leitura. Clique numa linha para selecionar seu bloco.</translation>
    </message>
    <message>
        <source>Loading %1 (%2 MB)...</source>
        <translation>Carregando %1 (%2 MB)...</translation>
    </message>
    <message>
        <source>No program is selected: there is no file to save to.</source>
        <translation>Nenhum programa selecionado: não há arquivo onde salvar.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::RailView</name>
    <message>
        <source>left end</source>
        <translation>fim esquerdo</translation>
    </message>
    <message>
        <source>centre</source>
        <translation>centro</translation>
    </message>
    <message>
        <source>right end</source>
        <translation>fim direito</translation>
    </message>
</context>
<context>
    <name>trilho::ui::RunControls</name>
    <message>
        <source>Cycle start</source>
        <translation>Início de ciclo</translation>
    </message>
    <message>
        <source>Feed hold</source>
        <translation>Suspender avanço</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continua</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>Single block</source>
        <translation>Bloco a bloco</translation>
    </message>
    <message>
        <source>Feed override -10 %</source>
        <translation>Correção de avanço -10 %</translation>
    </message>
    <message>
        <source>Feed override +10 %</source>
        <translation>Correção de avanço +10 %</translation>
    </message>
    <message>
        <source>Feed override 100 %</source>
        <translation>Correção de avanço 100 %</translation>
    </message>
    <message>
        <source>Feed override %1 %</source>
        <translation>Correção de avanço %1 %</translation>
    </message>
</context>
<context>
    <name>trilho::ui::RunOverlay</name>
    <message>
        <source>Rise time 10-90 % (ms)</source>
        <translation>Tempo de subida 10-90 % (ms)</translation>
    </message>
    <message>
        <source>Settling time 2 % (ms)</source>
        <translation>Tempo de acomodação 2 % (ms)</translation>
    </message>
    <message>
        <source>Settling time +-1 count (ms)</source>
        <translation>Tempo de acomodação +-1 contagem (ms)</translation>
    </message>
    <message>
        <source>Overshoot (%)</source>
        <translation>Sobressinal (%)</translation>
    </message>
    <message>
        <source>Peak (mm)</source>
        <translation>Pico (mm)</translation>
    </message>
    <message>
        <source>Peak time (ms)</source>
        <translation>Tempo de pico (ms)</translation>
    </message>
    <message>
        <source>Steady-state error (counts)</source>
        <translation>Erro em regime permanente (contagens)</translation>
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
        <translation>Erro de seguimento máx. (mm)</translation>
    </message>
    <message>
        <source>Following error RMS (mm)</source>
        <translation>Erro de seguimento RMS (mm)</translation>
    </message>
    <message>
        <source>Time saturated (ms)</source>
        <translation>Tempo saturado (ms)</translation>
    </message>
    <message>
        <source>no step</source>
        <translation>sem degrau</translation>
    </message>
    <message>
        <source>not reached</source>
        <translation>não atingido</translation>
    </message>
    <message>
        <source>time from the step (s)</source>
        <translation>tempo desde o degrau (s)</translation>
    </message>
    <message>
        <source>displacement (mm)</source>
        <translation>deslocamento (mm)</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Parado</translation>
    </message>
    <message>
        <source>no</source>
        <translation>não</translation>
    </message>
</context>
<context>
    <name>trilho::ui::SelectFileDialog</name>
    <message>
        <source>Select</source>
        <translation>Selecionar</translation>
    </message>
    <message>
        <source>Examples</source>
        <translation>Exemplos</translation>
    </message>
    <message>
        <source>Home folder</source>
        <translation>Pasta pessoal</translation>
    </message>
    <message>
        <source>Path</source>
        <translation>Caminho</translation>
    </message>
    <message>
        <source>Files</source>
        <translation>Arquivos</translation>
    </message>
    <message>
        <source>&amp;Open</source>
        <translation>&amp;Abrir</translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation>Sai&amp;r</translation>
    </message>
    <message>
        <source>Files (%1 for other machines not shown)</source>
        <translation>Arquivos (%1 de outras máquinas não mostrados)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::SimulationPanel</name>
    <message>
        <source>stuck encoder</source>
        <translation>encoder travado</translation>
    </message>
    <message>
        <source>amplifier trip</source>
        <translation>falha do amplificador</translation>
    </message>
    <message>
        <source>torn counter reads</source>
        <translation>leituras rasgadas do contador</translation>
    </message>
    <message>
        <source>lost counts above %1 counts/s</source>
        <translation>contagens perdidas acima de %1 contagens/s</translation>
    </message>
    <message>
        <source>cable slip %1</source>
        <translation>deslizamento do cabo %1</translation>
    </message>
    <message>
        <source>switch noise %1</source>
        <translation>ruído nas chaves %1</translation>
    </message>
    <message>
        <source>late ticks up to %1 ms (p %2)</source>
        <translation>ciclos atrasados até %1 ms (p %2)</translation>
    </message>
    <message>
        <source>Faults of the simulated rail, for teaching and rehearsal. They act at once; Clear all puts the rail right (acknowledge any alarm after).</source>
        <translation>Falhas do trilho simulado, para ensino e treino. Agem na hora; Limpar tudo restaura o trilho (reconheça os alarmes depois).</translation>
    </message>
    <message>
        <source>Stuck encoder</source>
        <translation>Encoder travado</translation>
    </message>
    <message>
        <source>Amplifier trip</source>
        <translation>Desarme do amplificador</translation>
    </message>
    <message>
        <source>Torn counter reads</source>
        <translation>Leituras partidas do contador</translation>
    </message>
    <message>
        <source>Lost counts above (counts/s, 0 = off):</source>
        <translation>Perda de contagens acima de (contagens/s, 0 = não):</translation>
    </message>
    <message>
        <source>Cable slip (fraction):</source>
        <translation>Escorregamento do cabo (fração):</translation>
    </message>
    <message>
        <source>Switch noise (probability per read):</source>
        <translation>Ruído nas chaves (probabilidade por leitura):</translation>
    </message>
    <message>
        <source>Late servo ticks, up to (ms):</source>
        <translation>Ciclos do servo atrasados, até (ms):</translation>
    </message>
    <message>
        <source>Late tick probability:</source>
        <translation>Probabilidade de atraso:</translation>
    </message>
    <message>
        <source>Clear all</source>
        <translation>Limpar tudo</translation>
    </message>
</context>
<context>
    <name>trilho::ui::StartScreen</name>
    <message>
        <source>Didactic D.N.C. system for the automatic rail</source>
        <translation>Sistema D.N.C. didático para trilho automático</translation>
    </message>
    <message>
        <source>University of São Paulo</source>
        <translation>Universidade de São Paulo</translation>
    </message>
    <message>
        <source>Polytechnic School</source>
        <translation>Escola Politécnica</translation>
    </message>
    <message>
        <source>Numerical Control for the robot&apos;s rail</source>
        <translation>Comando Numérico para trilho de comando do robô</translation>
    </message>
    <message>
        <source>Original design, 1996. Rebuilt and finished as trilho.</source>
        <translation>Projeto original de 1996. Reconstruído e concluído como trilho.</translation>
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
        <translation>Trilho do robô (1996)</translation>
    </message>
    <message>
        <source>DC-motor XY table</source>
        <translation>Mesa XY com motores CC</translation>
    </message>
    <message>
        <source>Stepper XY plotter</source>
        <translation>Plotter XY com motores de passo</translation>
    </message>
</context>
<context>
    <name>trilho::ui::TeachingSwitches</name>
    <message>
        <source>Teaching switches</source>
        <translation>Chaves didáticas</translation>
    </message>
    <message>
        <source>Anti-windup</source>
        <translation>Anti-windup</translation>
    </message>
    <message>
        <source>Off: the engineered law&apos;s integral winds while the drive is pinned (lesson 17)</source>
        <translation>Desligado: a integral da lei projetada acumula enquanto o acionamento está saturado (lição 17)</translation>
    </message>
    <message>
        <source>Encoder noise (counts)</source>
        <translation>Ruído do encoder (contagens)</translation>
    </message>
    <message>
        <source>The counter reads up to this many counts off, each tick, from the seed (lesson 18)</source>
        <translation>O contador lê até esse número de contagens a mais ou a menos, a cada período, a partir da semente (lição 18)</translation>
    </message>
    <message>
        <source>DAC quantization (8 bits)</source>
        <translation>Quantização do DAC (8 bits)</translation>
    </message>
    <message>
        <source>Off: the amplifier gets the loop&apos;s command unrounded (lesson 18)</source>
        <translation>Desligado: o amplificador recebe o comando da malha sem arredondamento (lição 18)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::TermsView</name>
    <message>
        <source>What if: the same run with other gains</source>
        <translation>E se: o mesmo ensaio com outros ganhos</translation>
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
        <translation>Simular de novo</translation>
    </message>
    <message>
        <source>Runs the recorded test again from the same start with these gains and adds it to the overlay</source>
        <translation>Executa de novo o ensaio gravado a partir do mesmo início com estes ganhos e o sobrepõe aos outros</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tempo (s)</translation>
    </message>
    <message>
        <source>PWM (%)</source>
        <translation>PWM (%)</translation>
    </message>
    <message>
        <source>DAC codes from 128</source>
        <translation>códigos DAC a partir de 128</translation>
    </message>
    <message>
        <source>This run has no loop terms (a trace of a program): record a step test to see them.</source>
        <translation>Este ensaio não tem termos da malha (é o registro de um programa): grave um teste de degrau para vê-los.</translation>
    </message>
    <message>
        <source>Run a step test, then choose its column in the table.</source>
        <translation>Execute um teste de degrau e escolha a coluna dele na tabela.</translation>
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
        <translation>soma antes da limitação</translation>
    </message>
    <message>
        <source>drive written</source>
        <translation>acionamento escrito</translation>
    </message>
    <message>
        <source>&lt;b&gt;Tick %1&lt;/b&gt;, t = %2 s, period T = %3 ms</source>
        <translation>&lt;b&gt;Ciclo %1&lt;/b&gt;, t = %2 s, período T = %3 ms</translation>
    </message>
    <message>
        <source>e[k] = r[k] - y[k] = %1 - %2 = &lt;b&gt;%3 mm&lt;/b&gt; (%4 counts)</source>
        <translation>e[k] = r[k] - y[k] = %1 - %2 = &lt;b&gt;%3 mm&lt;/b&gt; (%4 contagens)</translation>
    </message>
    <message>
        <source>P = Kp e = %1 x %2 = %3 %; I = %4 %; FF = Kff v_ref = %5 %</source>
        <translation>P = Kp e = %1 x %2 = %3 %; I = %4 %; FF = Kff v_ref = %5 %</translation>
    </message>
    <message>
        <source>u = P + I + FF = &lt;b&gt;%1 %&lt;/b&gt; -&gt; clamp -&gt; %2 % -&gt; PWM written %3 %</source>
        <translation>u = P + I + FF = &lt;b&gt;%1 %&lt;/b&gt; -&gt; limitação -&gt; %2 % -&gt; PWM escrito %3 %</translation>
    </message>
    <message>
        <source>The 1996 law: V[k] = floor(128 + Kp e[k] + (Kd / T) (e[k] - e[k-1]) + Ki sum(e) + 0.5), T in ms, clamped by M = F / 100</source>
        <translation>A lei de 1996: V[k] = floor(128 + Kp e[k] + (Kd / T) (e[k] - e[k-1]) + Ki sum(e) + 0.5), T em ms, limitado por M = F / 100</translation>
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
        <translation>I[k] = I[k-1] + Ki T e[k] = %1 códigos (Ki = %2; congelado enquanto a saída está saturada: anti-windup)</translation>
    </message>
    <message>
        <source>D = -Kd dy/dt (on the measurement, filtered: no kick when the setpoint jumps) = -%1 x %2 = %3 codes</source>
        <translation>D = -Kd dy/dt (sobre a medição, filtrado: sem pico quando o setpoint salta) = -%1 x %2 = %3 códigos</translation>
    </message>
    <message>
        <source>FF = (v_ref + tau a_ref) x 127 / v_max + Kd v_ref = %1 codes (v_ref = %2 mm/s)</source>
        <translation>FF = (v_ref + tau a_ref) x 127 / v_max + Kd v_ref = %1 códigos (v_ref = %2 mm/s)</translation>
    </message>
    <message>
        <source>u = P + I + D + FF = &lt;b&gt;%1 codes&lt;/b&gt; -&gt; clamp and slew limit -&gt; %2 -&gt; DAC = round(128 + u + carried fraction) = &lt;b&gt;%3&lt;/b&gt;%4</source>
        <translation>u = P + I + D + FF = &lt;b&gt;%1 códigos&lt;/b&gt; -&gt; limitação e limite de variação -&gt; %2 -&gt; DAC = round(128 + u + fração acumulada) = &lt;b&gt;%3&lt;/b&gt;%4</translation>
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
        <translation>Linha do tempo do histórico</translation>
    </message>
    <message>
        <source>Reading the history...</source>
        <translation>Lendo o histórico...</translation>
    </message>
    <message>
        <source>The history has no alarm, warning, hold, override, mode change or DNC write.</source>
        <translation>O histórico não tem alarme, aviso, espera, correção de avanço, mudança de modo nem escrita DNC.</translation>
    </message>
    <message>
        <source>Marks from the history: %1; times in seconds from its first entry. Click a mark to find it in the list.</source>
        <translation>Marcas do histórico: %1; tempos em segundos desde a primeira entrada. Clique numa marca para achá-la na lista.</translation>
    </message>
</context>
<context>
    <name>trilho::ui::TimelineStrip</name>
    <message>
        <source>Program start</source>
        <translation>Início do programa</translation>
    </message>
    <message>
        <source>Program end</source>
        <translation>Fim do programa</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarme</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Aviso</translation>
    </message>
    <message>
        <source>Acknowledged</source>
        <translation>Reconhecido</translation>
    </message>
    <message>
        <source>Held</source>
        <translation>Em espera</translation>
    </message>
    <message>
        <source>Resumed</source>
        <translation>Retomado</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>Parado</translation>
    </message>
    <message>
        <source>Feed override</source>
        <translation>Correção de avanço</translation>
    </message>
    <message>
        <source>Mode change</source>
        <translation>Mudança de modo</translation>
    </message>
    <message>
        <source>DNC write</source>
        <translation>Escrita DNC</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>linha %1</translation>
    </message>
</context>
<context>
    <name>trilho::ui::WorkbenchWindow</name>
    <message>
        <source>Tuning workbench: %1</source>
        <translation>Bancada de sintonia: %1</translation>
    </message>
    <message>
        <source>Margin test (simulated plotter, virtual time)</source>
        <translation>Teste de margem (plotter simulado, tempo virtual)</translation>
    </message>
    <message>
        <source>Step test (simulated plant, virtual time)</source>
        <translation>Teste de degrau (planta simulada, tempo virtual)</translation>
    </message>
    <message>
        <source>Run margin test</source>
        <translation>Executar teste de margem</translation>
    </message>
    <message>
        <source>Moves out and back at rising speed, then at rising acceleration, until one loses a step: the profile&apos;s margin against each</source>
        <translation>Movimentos de ida e volta a velocidade crescente, depois a aceleração crescente, até um perder um passo: a margem do perfil contra cada uma</translation>
    </message>
    <message>
        <source>Change gains during the test</source>
        <translation>Mudar os ganhos durante o teste</translation>
    </message>
    <message>
        <source>Bumpless: the integral takes the difference, the drive does not jump</source>
        <translation>Sem solavanco: a integral absorve a diferença, o acionamento não salta</translation>
    </message>
    <message>
        <source>At (s after the step)</source>
        <translation>Em (s após o degrau)</translation>
    </message>
    <message>
        <source>New Kp</source>
        <translation>Novo Kp</translation>
    </message>
    <message>
        <source>New Ki</source>
        <translation>Novo Ki</translation>
    </message>
    <message>
        <source>New Kd</source>
        <translation>Novo Kd</translation>
    </message>
    <message>
        <source>Axis</source>
        <translation>Eixo</translation>
    </message>
    <message>
        <source>Amplitude (mm)</source>
        <translation>Amplitude do degrau (mm)</translation>
    </message>
    <message>
        <source>The sign is the direction</source>
        <translation>O sinal indica o sentido</translation>
    </message>
    <message>
        <source>Speed (% of rapid)</source>
        <translation>Velocidade (% da máxima)</translation>
    </message>
    <message>
        <source>100 %: a step at the rapid speed; below: a ramp</source>
        <translation>100 %: um degrau na velocidade máxima; abaixo disso: uma rampa</translation>
    </message>
    <message>
        <source>Control law</source>
        <translation>Lei de controle</translation>
    </message>
    <message>
        <source>Engineered</source>
        <translation>Moderna</translation>
    </message>
    <message>
        <source>Classic (1996)</source>
        <translation>Clássico (1996)</translation>
    </message>
    <message>
        <source>Seed 004 (as written)</source>
        <translation>Seed 004 (como escrita)</translation>
    </message>
    <message>
        <source>Seed 004 signed</source>
        <translation>Seed 004 com sinal</translation>
    </message>
    <message>
        <source>Seed 004 as written: u = 100 (b0 |e| + b1 |e_prev|), the direction bit fixed for the move (past the target it drives on); signed: the same gains on the signed error (it drives back); engineered: feed-forward and PI</source>
        <translation>Seed 004 como escrita: u = 100 (b0 |e| + b1 |e_ant|), o bit de direção fixo no movimento (passado o alvo, segue acionando); com sinal: os mesmos ganhos sobre o erro com sinal (aciona de volta); engenheirada: feed-forward e PI</translation>
    </message>
    <message>
        <source>Period (ms)</source>
        <translation>Período (ms)</translation>
    </message>
    <message>
        <source>The 1996 law ran at 10 ms: its gains are per tick, so at 1 ms they act ten times harder (a lesson, not a setting)</source>
        <translation>A lei de 1996 rodava a 10 ms: seus ganhos são por ciclo, então a 1 ms agem dez vezes mais forte (uma lição, não um ajuste)</translation>
    </message>
    <message>
        <source>Seed 004 ran at 5 ms: its b0 and b1 are per tick, so at another period the same numbers are another law (a lesson, not a setting)</source>
        <translation>O seed 004 rodava a 5 ms: seus b0 e b1 são por período, então em outro período os mesmos números são outra lei (uma lição, não um ajuste)</translation>
    </message>
    <message>
        <source>Mass factor</source>
        <translation>Fator de massa</translation>
    </message>
    <message>
        <source>The plant&apos;s moving mass times this; the loop is not told</source>
        <translation>A massa móvel da planta vezes este fator; a malha não é informada</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Semente</translation>
    </message>
    <message>
        <source>Run step</source>
        <translation>Executar degrau</translation>
    </message>
    <message>
        <source>1996 law against engineered</source>
        <translation>Lei de 1996 contra a moderna</translation>
    </message>
    <message>
        <source>The same move with the 1996 law at its 10 ms and its gains, and with the engineered law</source>
        <translation>O mesmo movimento com a lei de 1996, com seus 10 ms e seus ganhos, e com a lei moderna</translation>
    </message>
    <message>
        <source>Identification and autotune</source>
        <translation>Identificação e sintonia automática</translation>
    </message>
    <message>
        <source>Identify the plant</source>
        <translation>Identificar a planta</translation>
    </message>
    <message>
        <source>At most 3 s of machine time, within 100 mm, back to the start within a count</source>
        <translation>No máximo 3 s de tempo de máquina, dentro de 100 mm, de volta ao início a menos de uma contagem</translation>
    </message>
    <message>
        <source>Autotune</source>
        <translation>Sintonia automática</translation>
    </message>
    <message>
        <source>Identify, design (SIMC), predict, then verify with a 10 mm step and a 1000 mm move</source>
        <translation>Identifica, projeta (SIMC), prevê e depois verifica com um degrau de 10 mm e um movimento de 1000 mm</translation>
    </message>
    <message>
        <source>Identify the axis, design (SIMC PI), predict, then verify with a 10 mm step and a 100 mm move</source>
        <translation>Identificar o eixo, projetar (PI SIMC), prever e então verificar com um degrau de 10 mm e um movimento de 100 mm</translation>
    </message>
    <message>
        <source>Relay experiment (Ziegler-Nichols)</source>
        <translation>Experimento do relé (Ziegler-Nichols)</translation>
    </message>
    <message>
        <source>To teach with, never the default: a relay of +-3 codes provokes a limit cycle, Ziegler-Nichols gains from it, beside the model-based gains, both on the same 10 mm step</source>
        <translation>Para ensinar, nunca o padrão: um relé de +-3 códigos provoca um ciclo limite, ganhos de Ziegler-Nichols a partir dele, ao lado dos ganhos baseados no modelo, ambos no mesmo degrau de 10 mm</translation>
    </message>
    <message>
        <source>Save tuned profile...</source>
        <translation>Salvar perfil sintonizado...</translation>
    </message>
    <message>
        <source>Runs</source>
        <translation>Ensaios</translation>
    </message>
    <message>
        <source>Save run...</source>
        <translation>Salvar ensaio...</translation>
    </message>
    <message>
        <source>Load run...</source>
        <translation>Carregar ensaio...</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Remover</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>Limpar</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <source>&amp;Export lab sheet...</source>
        <translation>&amp;Exportar folha de laboratório...</translation>
    </message>
    <message>
        <source>The runs shown, overlaid, with their gains, law, period, payload and metrics side by side: one A4 page, PDF or PNG</source>
        <translation>Os ensaios mostrados, sobrepostos, com seus ganhos, lei, período, carga e métricas lado a lado: uma página A4, PDF ou PNG</translation>
    </message>
    <message>
        <source>Margin</source>
        <translation>Margem</translation>
    </message>
    <message>
        <source>Responses</source>
        <translation>Respostas</translation>
    </message>
    <message>
        <source>P, I, D terms</source>
        <translation>Termos P, I, D</translation>
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
        <translation>Previsão</translation>
    </message>
    <message>
        <source>Disturbance</source>
        <translation>Perturbação</translation>
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
        <translation>Seed 004: u = 100 (b0 e + b1 e_ant) % de PWM, e em rad do motor, por período: 100 (b0 + b1) é seu ganho proporcional, -100 b1 uma diferença de e por período</translation>
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
        <translation>seed 004 com sinal</translation>
    </message>
    <message>
        <source>%1 %2, %3 mm at %4 ms, mass x%5</source>
        <translation>%1 %2, %3 mm a %4 ms, massa x%5</translation>
    </message>
    <message>
        <source>, then Kp %1 Ki %2 Kd %3 from %4 s</source>
        <translation>, depois Kp %1 Ki %2 Kd %3 a partir de %4 s</translation>
    </message>
    <message>
        <source>Running in virtual time...</source>
        <translation>Executando em tempo virtual...</translation>
    </message>
    <message>
        <source>Run %1 done.</source>
        <translation>Ensaio %1 concluído.</translation>
    </message>
    <message>
        <source>Run %1 stopped: %2</source>
        <translation>Ensaio %1 parado: %2</translation>
    </message>
    <message>
        <source>The gain change never came (%1): the run had one set of gains.</source>
        <translation>A mudança de ganhos não chegou (%1): a execução teve um só conjunto de ganhos.</translation>
    </message>
    <message>
        <source>what if (from run %1): %2</source>
        <translation>e se (do ensaio %1): %2</translation>
    </message>
    <message>
        <source>Identified: fit %1 % on held-out velocity.</source>
        <translation>Identificado: ajuste de %1 % na velocidade de validação.</translation>
    </message>
    <message>
        <source>Model refused: %1</source>
        <translation>Modelo recusado: %1</translation>
    </message>
    <message>
        <source>Autotune passed in %1 s of machine time.</source>
        <translation>Sintonia automática aprovada em %1 s de tempo de máquina.</translation>
    </message>
    <message>
        <source>Autotune failed: %1</source>
        <translation>Sintonia automática falhou: %1</translation>
    </message>
    <message>
        <source>Relay: Ku %1 code/mm, Tu %2 ms.</source>
        <translation>Relé: Ku %1 código/mm, Tu %2 ms.</translation>
    </message>
    <message>
        <source>Relay experiment failed: %1</source>
        <translation>O experimento do relé falhou: %1</translation>
    </message>
    <message>
        <source>Margin test done: speed margin %1, acceleration margin %2.</source>
        <translation>Teste de margem feito: margem de velocidade %1, margem de aceleração %2.</translation>
    </message>
    <message>
        <source>Margin test refused: %1</source>
        <translation>Teste de margem recusado: %1</translation>
    </message>
    <message>
        <source>No run is selected.</source>
        <translation>Nenhum ensaio selecionado.</translation>
    </message>
    <message>
        <source>Saving %1...</source>
        <translation>Salvando %1...</translation>
    </message>
    <message>
        <source>Saved %1 and %2.</source>
        <translation>Salvos %1 e %2.</translation>
    </message>
    <message>
        <source>Loading %1...</source>
        <translation>Carregando %1...</translation>
    </message>
    <message>
        <source>Load run</source>
        <translation>Carregar ensaio</translation>
    </message>
    <message>
        <source>%1: the run has no samples</source>
        <translation>%1: o ensaio não tem amostras</translation>
    </message>
    <message>
        <source>The run&apos;s events are not shown: %1</source>
        <translation>Os eventos da execução não são mostrados: %1</translation>
    </message>
    <message>
        <source>Save run</source>
        <translation>Salvar ensaio</translation>
    </message>
    <message>
        <source>Run records (*.csv)</source>
        <translation>Registros de ensaio (*.csv)</translation>
    </message>
    <message>
        <source>Run records and traces (*.csv)</source>
        <translation>Registros de ensaio e traços (*.csv)</translation>
    </message>
    <message>
        <source>Save tuned profile</source>
        <translation>Salvar perfil sintonizado</translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation>Perfis de máquina (*.json)</translation>
    </message>
    <message>
        <source>Saved %1: trilho-cli run --machine %1 uses it.</source>
        <translation>Salvo %1: trilho-cli run --machine %1 o usa.</translation>
    </message>
    <message>
        <source>&apos;%1&apos;: a lab sheet is a .pdf or a .png file</source>
        <translation>&apos;%1&apos;: uma folha de laboratório é um arquivo .pdf ou .png</translation>
    </message>
    <message>
        <source>No run is shown: there is nothing to put on a lab sheet.</source>
        <translation>Nenhum ensaio está mostrado: não há o que pôr numa folha de laboratório.</translation>
    </message>
    <message>
        <source>%1 runs are shown: at most %2 fit one sheet (untick some in the runs&apos; list)</source>
        <translation>%1 ensaios estão mostrados: no máximo %2 cabem numa folha (desmarque alguns na lista de ensaios)</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Imagem PNG (*.png)</translation>
    </message>
    <message>
        <source>Export lab sheet</source>
        <translation>Exportar folha de laboratório</translation>
    </message>
    <message>
        <source>Lab sheet written: %1</source>
        <translation>Folha de laboratório gravada: %1</translation>
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
        <translation>AUTOMÁTICO - pronto</translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation>REFERENCIANDO</translation>
    </message>
    <message>
        <source>RUNNING</source>
        <translation>EXECUTANDO</translation>
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
        <translation>ALARME</translation>
    </message>
    <message>
        <source>E-STOP LATCHED</source>
        <translation>EMERGÊNCIA ACIONADA</translation>
    </message>
    <message>
        <source>Stop the machine before changing the connection.</source>
        <translation>Pare a máquina antes de mudar a conexão.</translation>
    </message>
    <message>
        <source>Feed override %1 %</source>
        <translation>Correção de avanço %1 %</translation>
    </message>
    <message>
        <source>Loading %1 (%2 MB)...</source>
        <translation>Carregando %1 (%2 MB)...</translation>
    </message>
    <message>
        <source>the pen lifts and the carriage runs to the origin sensors, where both axes are zeroed (0, 0).</source>
        <translation>a caneta sobe e o carro vai até os sensores de origem, onde os dois eixos são zerados (0, 0).</translation>
    </message>
    <message>
        <source>the DC table has no home switch: it travels at full speed to (0, 0), its origin (where it stood at power-on).</source>
        <translation>a mesa CC não tem chave de referência: vai em velocidade máxima até (0, 0), sua origem (onde estava ao ligar).</translation>
    </message>
    <message>
        <source>the DC table has no home switch: its origin is where it stood at power-on, and nothing moves.</source>
        <translation>a mesa CC não tem chave de referência: sua origem é onde estava ao ligar, e nada se move.</translation>
    </message>
    <message>
        <source> (first programmed move to (%1, %2) mm)</source>
        <translation> (primeiro movimento programado para (%1, %2) mm)</translation>
    </message>
    <message>
        <source>It starts the program where homing leaves it, at the origin (0.0, 0.0) mm, where every program starts%1.</source>
        <translation>Começa o programa onde a referência a deixa, na origem (0.0, 0.0) mm, onde todo programa começa%1.</translation>
    </message>
    <message>
        <source>It starts the program where it stands, at the origin (0.0, 0.0) mm, where every program starts%1.</source>
        <translation>Começa o programa onde está, na origem (0.0, 0.0) mm, onde todo programa começa%1.</translation>
    </message>
    <message>
        <source>The machine travels at full speed from (%1, %2) mm to the origin (0.0, 0.0) mm, where every program starts, then runs it%3.</source>
        <translation>A máquina vai em velocidade máxima de (%1, %2) mm até a origem (0.0, 0.0) mm, onde todo programa começa, e então o executa%3.</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automático</translation>
    </message>
    <message>
        <source>Automatic homes the machine first: %1 Go on?</source>
        <translation>O modo automático primeiro referencia a máquina: %1 Continuar?</translation>
    </message>
    <message>
        <source>Home: stop the machine (or reset the E-stop, acknowledge the alarm) first.</source>
        <translation>Referenciar: pare a máquina (ou rearme a emergência, reconheça o alarme) antes.</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Referenciar</translation>
    </message>
    <message>
        <source>Home the machine? %1</source>
        <translation>Referenciar a máquina? %1</translation>
    </message>
    <message>
        <source>Run %1? %2%3</source>
        <translation>Executar %1? %2%3</translation>
    </message>
    <message>
        <source>Its position is not known, so it homes first: %1 </source>
        <translation>A posição não é conhecida, então primeiro faz a referência: %1 </translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation>Início de ciclo</translation>
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
        <translation>O histórico não pôde ser gravado: %1</translation>
    </message>
    <message>
        <source>The simulated machine started again at its origin: the run that was going is lost.</source>
        <translation>A máquina simulada recomeçou na origem: a execução em curso se perdeu.</translation>
    </message>
    <message>
        <source>Positions are unknown until homed: the plotter&apos;s protocol has no question the board answers with where it stands.</source>
        <translation>As posições são desconhecidas até a referência: o protocolo do plotter não tem pergunta à qual a placa responda onde está.</translation>
    </message>
    <message>
        <source>Positions are unknown until homed; the board is asked which set point it last ran.</source>
        <translation>As posições são desconhecidas até a referência; a placa é consultada sobre o último ponto de ajuste que executou.</translation>
    </message>
    <message>
        <source>unknown until homed</source>
        <translation>desconhecida até a referência</translation>
    </message>
    <message>
        <source>the board&apos;s last set point, not homed</source>
        <translation>último ponto de ajuste da placa, sem referência</translation>
    </message>
    <message>
        <source>planned, unconfirmed: the seed&apos;s board answers nothing</source>
        <translation>planejada, não confirmada: a placa do seed não responde nada</translation>
    </message>
    <message>
        <source>Block N%1, line %2</source>
        <translation>Bloco N%1, linha %2</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Linha %1</translation>
    </message>
    <message>
        <source>Simulated machine</source>
        <translation>Máquina simulada</translation>
    </message>
    <message>
        <source>LINK LOST</source>
        <translation>LIGAÇÃO PERDIDA</translation>
    </message>
    <message>
        <source>link up</source>
        <translation>ligação ativa</translation>
    </message>
    <message>
        <source>port open; the seed&apos;s board answers nothing: position planned, unconfirmed</source>
        <translation>porta aberta; a placa do seed não responde nada: posição planejada, não confirmada</translation>
    </message>
    <message>
        <source>port open, no answer yet</source>
        <translation>porta aberta, ainda sem resposta</translation>
    </message>
    <message>
        <source>%1 at %2 bit/s: %3 - packets %4, RESENDs %5, timeouts %6</source>
        <translation>%1 a %2 bit/s: %3 - pacotes %4, RESENDs %5, tempos esgotados %6</translation>
    </message>
    <message>
        <source>%1 at %2 bit/s: %3 - set points sent %4 (no acknowledgement)</source>
        <translation>%1 a %2 bit/s: %3 - ajustes enviados %4 (sem confirmação)</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Conexão</translation>
    </message>
    <message>
        <source>Simulated machine (no hardware)</source>
        <translation>Máquina simulada (sem hardware)</translation>
    </message>
    <message>
        <source>Board on a serial port</source>
        <translation>Placa numa porta serial</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Porta</translation>
    </message>
    <message>
        <source>Bit rate</source>
        <translation>Velocidade (bit/s)</translation>
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
        <translation>Automático (referência)</translation>
    </message>
    <message>
        <source>Cycle start (F5)</source>
        <translation>Início de ciclo (F5)</translation>
    </message>
    <message>
        <source>Feed hold (F6)</source>
        <translation>Suspender avanço (F6)</translation>
    </message>
    <message>
        <source>Continue (F7)</source>
        <translation>Continua (F7)</translation>
    </message>
    <message>
        <source>Stop (F8)</source>
        <translation>Parar (F8)</translation>
    </message>
    <message>
        <source>Single block (F9)</source>
        <translation>Bloco a bloco (F9)</translation>
    </message>
    <message>
        <source>Feed hold</source>
        <translation>Suspender avanço</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Continua</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>Single block</source>
        <translation>Bloco a bloco</translation>
    </message>
    <message>
        <source>Feed override -10 %</source>
        <translation>Correção de avanço -10 %</translation>
    </message>
    <message>
        <source>Feed override +10 %</source>
        <translation>Correção de avanço +10 %</translation>
    </message>
    <message>
        <source>Feed override 100 %</source>
        <translation>Correção de avanço 100 %</translation>
    </message>
    <message>
        <source>&amp;Open program...</source>
        <translation>&amp;Abrir programa...</translation>
    </message>
    <message>
        <source>&amp;Connection...</source>
        <translation>&amp;Conexão...</translation>
    </message>
    <message>
        <source>Ca&amp;libration...</source>
        <translation>Ca&amp;libração...</translation>
    </message>
    <message>
        <source>Polygon from &amp;points...</source>
        <translation>Polígono por &amp;pontos...</translation>
    </message>
    <message>
        <source>The plotter has no encoder: its workbench is the speed and acceleration margin test against lost steps</source>
        <translation>O plotter não tem encoder: sua bancada é o teste de margem de velocidade e aceleração contra passos perdidos</translation>
    </message>
    <message>
        <source>Program: %1</source>
        <translation>Programa: %1</translation>
    </message>
    <message>
        <source>No program loaded</source>
        <translation>Nenhum programa carregado</translation>
    </message>
</context>
<context>
    <name>trilho::ui::XyPlots</name>
    <message>
        <source>x set point</source>
        <translation>ajuste x</translation>
    </message>
    <message>
        <source>x planned (unconfirmed)</source>
        <translation>posição x planejada (não confirmada)</translation>
    </message>
    <message>
        <source>x: the board&apos;s last set point</source>
        <translation>x: o último ajuste da placa</translation>
    </message>
    <message>
        <source>x position</source>
        <translation>posição x</translation>
    </message>
    <message>
        <source>y set point</source>
        <translation>ajuste y</translation>
    </message>
    <message>
        <source>y planned (unconfirmed)</source>
        <translation>posição y planejada (não confirmada)</translation>
    </message>
    <message>
        <source>y: the board&apos;s last set point</source>
        <translation>y: o último ajuste da placa</translation>
    </message>
    <message>
        <source>y position</source>
        <translation>posição y</translation>
    </message>
    <message>
        <source>x set-point speed</source>
        <translation>velocidade do ajuste x</translation>
    </message>
    <message>
        <source>x speed: not reported on a line</source>
        <translation>velocidade x: não informada na linha</translation>
    </message>
    <message>
        <source>y set-point speed</source>
        <translation>velocidade do ajuste y</translation>
    </message>
    <message>
        <source>y speed: not reported on a line</source>
        <translation>velocidade y: não informada na linha</translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation>posição (mm)</translation>
    </message>
    <message>
        <source>speed (mm/s)</source>
        <translation>velocidade (mm/s)</translation>
    </message>
</context>
<context>
    <name>trilho::ui::XySimulationPanel</name>
    <message>
        <source>%1 axis jammed</source>
        <translation>eixo %1 travado</translation>
    </message>
    <message>
        <source>%1 encoder stuck</source>
        <translation>encoder %1 parado</translation>
    </message>
    <message>
        <source>lost steps above %1 steps/s</source>
        <translation>passos perdidos acima de %1 passos/s</translation>
    </message>
    <message>
        <source>origin sensors dead</source>
        <translation>sensores de origem mortos</translation>
    </message>
    <message>
        <source>Faults of the simulated plotter, for teaching and rehearsal. They act at once; Clear all puts the plotter right (home again after lost steps).</source>
        <translation>Falhas do plotter simulado, para ensino e treino. Agem na hora; Limpar tudo deixa o plotter em ordem (referencie de novo depois de passos perdidos).</translation>
    </message>
    <message>
        <source>Lost steps above (steps/s, 0 = off):</source>
        <translation>Passos perdidos acima de (passos/s, 0 = desligado):</translation>
    </message>
    <message>
        <source>Origin sensors dead (homing gives up)</source>
        <translation>Sensores de origem mortos (a referência desiste)</translation>
    </message>
    <message>
        <source>Faults of the simulated table, for teaching and rehearsal. They act at once; Clear all puts the table right (acknowledge any alarm after).</source>
        <translation>Falhas da mesa simulada, para ensino e treino. Agem na hora; Limpar tudo deixa a mesa em ordem (reconheça depois qualquer alarme).</translation>
    </message>
    <message>
        <source>X axis jammed</source>
        <translation>Eixo X travado</translation>
    </message>
    <message>
        <source>Y axis jammed</source>
        <translation>Eixo Y travado</translation>
    </message>
    <message>
        <source>X encoder stuck</source>
        <translation>Encoder X parado</translation>
    </message>
    <message>
        <source>Y encoder stuck</source>
        <translation>Encoder Y parado</translation>
    </message>
    <message>
        <source>Clear all</source>
        <translation>Limpar tudo</translation>
    </message>
</context>
</TS>
