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
        <source>Stopped</source>
        <translation>Parado</translation>
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
        <source>%1: Return to the machine&apos;s absolute zero.</source>
        <translation>%1: Retorno ao zero absoluto da máquina.</translation>
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
    <name>trilho::ui::DcTablePanel</name>
    <message>
        <source>Set point</source>
        <translation>Ponto de ajuste</translation>
    </message>
    <message>
        <source>X set point</source>
        <translation>Ponto de ajuste X</translation>
    </message>
    <message>
        <source>Y set point</source>
        <translation>Ponto de ajuste Y</translation>
    </message>
    <message>
        <source>&amp;Send</source>
        <translation>&amp;Enviar</translation>
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
        <source>Serial port</source>
        <translation>Porta serial</translation>
    </message>
    <message>
        <source>The table runs on the simulated machine; the serial link to the ATmega128 board comes in a later version.</source>
        <translation>A mesa roda na máquina simulada; a ligação serial com a placa ATmega128 vem numa versão posterior.</translation>
    </message>
    <message>
        <source>Port</source>
        <translation>Porta</translation>
    </message>
    <message>
        <source>Bit rate</source>
        <translation>Velocidade (bit/s)</translation>
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
        <translation>Biblioteca de programas</translation>
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
        <source>acknowledged</source>
        <translation>reconhecido</translation>
    </message>
    <message>
        <source>status</source>
        <translation>estado</translation>
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
</context>
<context>
    <name>trilho::ui::JogPanel</name>
    <message>
        <source>◀ hold to jog</source>
        <translation>◀ segure para mover</translation>
    </message>
    <message>
        <source>hold to jog ▶</source>
        <translation>segure para mover ▶</translation>
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
    <name>trilho::ui::MachineLink</name>
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
        <source>Start %1 from block %2? %3The rail moves at once, at rapid speed, %4.</source>
        <translation>Iniciar %1 a partir do bloco %2? %3O trilho move-se imediatamente, em velocidade rápida, %4.</translation>
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
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <source>&amp;Select</source>
        <translation>&amp;Selecionar</translation>
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
        <source>&amp;Compile file</source>
        <translation>&amp;Compilar arquivo</translation>
    </message>
    <message>
        <source>&amp;Execute file</source>
        <translation>&amp;Executar arquivo</translation>
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
        <source>&amp;Windows</source>
        <translation>&amp;Janelas</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>&amp;Restaurar disposição</translation>
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
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>Avanço manual</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Histórico</translation>
    </message>
    <message>
        <source>Rail</source>
        <translation>Trilho</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulação</translation>
    </message>
    <message>
        <source>Program library</source>
        <translation>Biblioteca de programas</translation>
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
        <source>E-STOP LATCHED</source>
        <translation>EMERGÊNCIA ACIONADA</translation>
    </message>
    <message>
        <source>E-STOP (Pause, F1)</source>
        <translation>EMERGÊNCIA (Pause, F1)</translation>
    </message>
    <message>
        <source>EMERGENCY STOP LATCHED: the drive is off. Clear the cause, then Reset E-stop.</source>
        <translation>PARADA DE EMERGÊNCIA TRAVADA: o acionamento está desligado. Elimine a causa e depois Liberar emergência.</translation>
    </message>
    <message>
        <source>Reset E-stop</source>
        <translation>Liberar emergência</translation>
    </message>
    <message>
        <source>Safety</source>
        <translation>Segurança</translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation>Reconhecer</translation>
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
        <source>Cycle start</source>
        <translation>Início de ciclo</translation>
    </message>
    <message>
        <source>Execute %1? %3The rail moves %2, then runs the program.</source>
        <translation>Executar %1? %3O trilho move-se %2, e então executa o programa.</translation>
    </message>
    <message>
        <source>from x = %1 mm to x = %2 mm</source>
        <translation>de x = %1 mm para x = %2 mm</translation>
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
        <translation>Emergência: elimine a causa e então Rearme a emergência.</translation>
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
    <message>
        <source>Simulated fault armed: %1</source>
        <translation>Falha simulada ativa: %1</translation>
    </message>
    <message>
        <source>Set in the Simulation dock; Clear all there puts the rail right.</source>
        <translation>Definida no painel Simulação; Limpar tudo lá corrige o trilho.</translation>
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
        <source>Saves atomically: a crash never leaves half a file</source>
        <translation>Salva de forma atômica: uma falha nunca deixa meio arquivo</translation>
    </message>
    <message>
        <source>No program is selected: there is no file to save to.</source>
        <translation>Nenhum programa selecionado: não há arquivo onde salvar.</translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation>não foi possível salvar &apos;%1&apos;: %2</translation>
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
    <name>trilho::ui::SelectFileDialog</name>
    <message>
        <source>Select</source>
        <translation>Selecionar</translation>
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
        <source>E&amp;xit</source>
        <translation>Sai&amp;r</translation>
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
        <source>&amp;File</source>
        <translation>&amp;Arquivo</translation>
    </message>
    <message>
        <source>&amp;Open program...</source>
        <translation>&amp;Abrir programa...</translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation>Sai&amp;r</translation>
    </message>
    <message>
        <source>&amp;Command</source>
        <translation>&amp;Comando</translation>
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
        <source>&amp;Options</source>
        <translation>&amp;Opções</translation>
    </message>
    <message>
        <source>&amp;Connection...</source>
        <translation>&amp;Conexão...</translation>
    </message>
    <message>
        <source>Polygon from &amp;points...</source>
        <translation>Polígono por &amp;pontos...</translation>
    </message>
    <message>
        <source>the pen lifts and the carriage runs to the origin sensors, where both axes are zeroed (0, 0).</source>
        <translation>a caneta sobe e o carro vai até os sensores de origem, onde os dois eixos são zerados (0, 0).</translation>
    </message>
    <message>
        <source>the DC table has no home switch: its origin is where it stood at power-on, and nothing moves.</source>
        <translation>a mesa CC não tem chave de referência: sua origem é onde estava ao ligar, e nada se move.</translation>
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
        <source>Cycle start</source>
        <translation>Início de ciclo</translation>
    </message>
    <message>
        <source>Run %1? %2The machine travels at full speed from (%3, %4) mm to the program&apos;s start, then runs it.</source>
        <translation>Executar %1? %2A máquina vai em velocidade máxima de (%3, %4) mm até o início do programa, e então o executa.</translation>
    </message>
    <message>
        <source>Its position is not known, so it homes first: %1 </source>
        <translation>A posição não é conhecida, então primeiro faz a referência: %1 </translation>
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
        <source>Block N%1, line %2</source>
        <translation>Bloco N%1, linha %2</translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation>Linha %1</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>Não foi possível gravar %1: %2</translation>
    </message>
    <message>
        <source>Simulated machine</source>
        <translation>Máquina simulada</translation>
    </message>
    <message>
        <source>%1 at %2 bit/s: %3 - packets %4, RESENDs %5, timeouts %6</source>
        <translation>%1 a %2 bit/s: %3 - pacotes %4, RESENDs %5, tempos esgotados %6</translation>
    </message>
    <message>
        <source>link up</source>
        <translation>ligação ativa</translation>
    </message>
    <message>
        <source>LINK LOST</source>
        <translation>LIGAÇÃO PERDIDA</translation>
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
        <source>Stop the machine before changing the connection.</source>
        <translation>Pare a máquina antes de mudar a conexão.</translation>
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
        <translation>Iniciar ciclo (F5)</translation>
    </message>
    <message>
        <source>Hold (F6)</source>
        <translation>Suspender (F6)</translation>
    </message>
    <message>
        <source>Resume (F7)</source>
        <translation>Retomar (F7)</translation>
    </message>
    <message>
        <source>Stop (F8)</source>
        <translation>Parar (F8)</translation>
    </message>
    <message>
        <source>E-STOP (Pause, F1)</source>
        <translation>EMERGÊNCIA (Pause, F1)</translation>
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
        <source>x position</source>
        <translation>posição x</translation>
    </message>
    <message>
        <source>y set point</source>
        <translation>ajuste y</translation>
    </message>
    <message>
        <source>y position</source>
        <translation>posição y</translation>
    </message>
    <message>
        <source>x speed</source>
        <translation>velocidade x</translation>
    </message>
    <message>
        <source>y speed</source>
        <translation>velocidade y</translation>
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
</TS>
