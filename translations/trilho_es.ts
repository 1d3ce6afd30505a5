<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>Controller</name>
    <message>
        <source>%1: Positioning to x=%2 at maximum speed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Positioning to x=%2 at %3% of maximum speed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Waiting %2 seconds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Change to absolute coordinates.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Change to incremental coordinates.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: System zero changed to x=%2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Return to the rail&apos;s absolute zero.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Feed set to %3% of maximum speed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Waiting for the Continue key.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Program jumped to line %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program finished !</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There are %2 compile error(s)! Nothing moved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing: going to the rail centre.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing done: platform at the rail centre.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Careful: left end of travel reached !!!</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Careful: right end of travel reached !!!</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum manual speed reached: lower the speed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program paused by the operator.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program resumed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program stopped by the operator.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continue pressed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Single block: press Continue for the next block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting from block %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm %2 acknowledged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency stop reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>POSITIONING</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>WAITING</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Absolute coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Incremental coordinates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System zero changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rail zero restored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Press Continue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program jump</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program ended !</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compile error(s)!</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PAUSED</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left end of travel reached ! The end switch cut the drive. Acknowledge, then in Manual drive the platform to the right, back inside the limits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right end of travel reached ! The end switch cut the drive. Acknowledge, then in Manual drive the platform to the left, back inside the limits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Following error: the platform did not follow the command (a jam, too heavy a load or a broken encoder cable) and the drive was cut. Free the rail, acknowledge, then home again with Automatic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Soft limit reached at x=%1 mm: the platform stopped there. Move it back the other way, inside the limits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program has compile errors: nothing moved. Correct the lines the diagnostics name, then run it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder fault: the counter gave implausible readings again and again, and the drive was cut. Check the encoder and its cable, acknowledge, then home again with Automatic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Amplifier fault: the amplifier reported it is not ready and the drive was cut. Check its power, fuse and temperature, acknowledge, then home again with Automatic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control interrupted: the computer ran the position control too late, so the drive was cut for safety. Close other heavy programs, acknowledge, then home again with Automatic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency stop: the drive was cut. Clear the cause, then press Reset E-stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing failed: the centre switch was not found. Check the switch and its cable, acknowledge, then home again with Automatic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Soft limit: the platform would have passed the soft limit at x=%1 mm and was stopped before the end switch. Acknowledge, then move it back inside the limits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not in position: the platform did not settle on its target (%1 mm off). Check the payload and the gains, acknowledge, then run again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program ended with the platform %1 mm from its last target, outside the final-position window. Check the payload and the gains, then run it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The centre mark corrected the position by %1 mm: counts were lost or the cable slipped. The position is right again; if this repeats, check the encoder and its cable.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motionless loop: the program repeats blocks that neither move nor wait. It is held: press Stop, or Continue to run it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Encoder stalled: the drive ran %1 mm without a single count and was cut. Check the encoder and its cable, acknowledge, then home again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Over-current: a motor drew too much current at %1 % PWM and its drive was cut. Free the axis, acknowledge, then home again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steps lost: homing found the origin %1 mm from where the counted steps put it. Lower the speed, acknowledge, then home again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing failed: the origin sensor was not found. Check the sensor and its cable, acknowledge, then home again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Link to the device lost: it did not answer, the line was too noisy, or the cable was pulled. The run is held: check the cable and the port, then press Continue to go on from the first point not acknowledged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Counts lost: the count differs by %1 mm from the travel the drive made, so the position is wrong and the drive was cut. Lower the speed or check the encoder and its counter card, acknowledge, then home again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Travel to x=%2 y=%4 at maximum speed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Line to x=%2 y=%4 at %3% of maximum speed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing: going to the origin.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing done: at the origin.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: Return to the machine&apos;s absolute zero.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Diagnostic</name>
    <message>
        <source>every line must start with n (found &apos;%2&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wrong n sequence %1: must be greater than %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sequence number alone %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>separating spaces required %1 (found &apos;%2&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>there can be no more commands after %2 %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>g00 requires an x word %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>g01 requires an x word %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>g04 without x word (time) %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>g92 requires an x word %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m03 without x word (block) %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid value after g04 %1: the time %2 is negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid value after m03 %1: the block %2 is negative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>negative f command impossible %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid g command %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid m command %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>g01 or g00 not defined %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>g01 needs f defined %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character or g00 does not take f %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character %1: &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character %1: malformed number &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character %1: &apos;%2&apos; must have exactly %3 digits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character %1: comment not closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character %1: word &apos;%2&apos; repeated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character %1: n must be the first word (&apos;%2&apos;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid value after m03 %1: &apos;%2&apos; is not a block number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid character %1: number &apos;%2&apos; longer than %3 digits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>program requires m02 (END) at the end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid GO TO %1: block n=%2 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed f%2 out of range %1: must be from %3 % to 100 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>target %2 mm %1 is beyond the soft limit %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>axis %2 %1 does not exist on this machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>block number &apos;%2&apos; too large %1: at most %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value &apos;%2&apos; too large %1: at most %3 in magnitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in block n=%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compilation completed successfully</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 compile error(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>... and %1 more diagnostic(s) not listed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho</name>
    <message>
        <source>the servo refused the drive (a limit or an end switch)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the servo faulted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the platform left the experiment&apos;s +-100 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the platform did not come back within one count of its start (%1 mm away)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 held to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the verification move with the tuned gains did not end in position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the experiment recorded too little</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the model fits the held-out run at %1 % on velocity, under %2 %</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::SerialLine</name>
    <message>
        <source>serial port %1: %2 (was the device unplugged?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open serial port %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot set %1 bit/s 8N1 on serial port %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::DcTablePanel</name>
    <message>
        <source>Set point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X set point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y set point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Send</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The table runs on the simulated machine; the serial link to the ATmega128 board comes in a later version.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit rate</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::DncDialog</name>
    <message>
        <source>Programs folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The address &apos;%1&apos; is not an IP address: write a numeric address such as 127.0.0.1 (this computer only), or 0.0.0.0 for every network interface.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The port must be a whole number from 1 to 65535 (got &apos;%1&apos;); Modbus TCP&apos;s own is 502, which needs administrator rights: 1502 does not.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus RTU needs the serial device, e.g. /dev/ttyUSB0 (or turn RTU off).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning: %1 can be reached from other computers. Modbus has no password and no encryption: anyone on that network can read this machine and, while Remote is on, change its gains and run programs. Use 127.0.0.1 unless the cell&apos;s network is closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DNC: off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DNC link (Modbus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serve the DNC link (Modbus) for the cell&apos;s supervisor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus TCP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Address:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus RTU on a serial line (8N1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit id:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading is always allowed. Writes and commands need Remote (Options &gt; Remote, Ctrl+Shift+R), which is off at every start.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::DncLink</name>
    <message>
        <source>Cannot listen on %1:%2: %3. Another program (another trilho?) may be using this port: choose another port or stop that program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DNC: cannot listen on %1:%2 (port taken?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open the serial device %1 for Modbus RTU: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DNC: cannot open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DNC: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DNC: %1, %2, %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remote ON</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remote off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 client</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 clients</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::DroPanel</name>
    <message>
        <source>Machine X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To go</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>zero %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F %1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>override %1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>classic law</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>engineered law</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cycle %1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dwell %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block %1 / %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::ExecutionPanel</name>
    <message>
        <source>Alarms :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic Mode :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual Mode :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current Data :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Proportional :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Derivative :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Integral :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Setpoint :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Actual value :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error :</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::HistoryPanel</name>
    <message>
        <source>Export history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>alarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acknowledged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge alarms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::JogPanel</name>
    <message>
        <source>◀ hold to jog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hold to jog ▶</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog speed %1 mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::KeysDialog</name>
    <message>
        <source>EMERGENCY STOP, in every window, menu and dialog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop (a controlled stop) when no menu, list or dialog is open; otherwise it only closes it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>STOP: the manual PARA, or Stop in automatic (not in the editor)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual mode: left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual mode: right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Action</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::MachineLink</name>
    <message>
        <source>Command not taken: the servo thread&apos;s queue is full. Press again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program not started: the servo thread is still taking the one before it, or its queue is full. Press again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::MainWindow</name>
    <message>
        <source>Start from a block runs in Automatic: choose Command &gt; Automatic first (it homes the rail).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start from the selected block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start %1 from block %2? %3The rail moves at once, at rapid speed, %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its position is not known, so it homes first: %1 </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Didactic D.N.C. system for the automatic rail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Select</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;ommand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home (Ctrl+Home)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Compile file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Execute file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>O&amp;ptions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Theme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Classic (1996 colours)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control &amp;law</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Classic (the 1996 difference equation)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Engineered (profile, feed-forward)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code &amp;dialect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Standard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Classic (1996)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Windows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tuning &amp;workbench...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keys</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>History</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program library</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;DNC link...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Remote (DNC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Allow the cell&apos;s supervisor to write and command over the DNC link (%1). Off at every start.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E-STOP LATCHED</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E-STOP (Pause, F1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EMERGENCY STOP LATCHED: the drive is off. Clear the cause, then Reset E-stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset E-stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Safety</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select the file first !</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program is loading: it compiles when it is loaded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compiling %1 MB...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>End</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compilation finished !</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Execute %1? %3The rail moves %2, then runs the program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>from x = %1 mm to x = %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (the rail centre, where every program starts, as in the 1996 program)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (first programmed move to x = %1 mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the rail drives right until a switch: the centre mark if it is left of the centre; otherwise the right end switch (about x = +%1 mm), then back left to the centre mark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the rail drives right from x = %1 mm to the centre mark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the rail drives right from x = %1 mm to the right end switch (about x = +%2 mm), then back left to the centre mark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1, and stops at x = 0.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic homes the rail first, as in 1996: %1 Home now?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home: stop the rail (or reset the E-stop, acknowledge the alarm) first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home the rail? %1%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> It then stays in Automatic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There are compile error(s)!</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Late ticks: %1 (longest %2 ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 status lines not shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic, ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The history could not be written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency stop: clear the cause, then Reset E-stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm: read it in Alarms, then Acknowledge. Execute then homes the rail first if its position was lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarm: read it in Alarms, then Acknowledge.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The rail&apos;s position is not known: Execute (or Automatic) homes it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Held: Resume goes on, Stop ends the program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cycle start runs in Automatic: choose Command &gt; Automatic first (it homes the rail).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program has unsaved changes. Save them before leaving?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The rail is moving (x = %1 mm, towards x = %2 mm). Exit stops it with an emergency stop. Exit now?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated fault armed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set in the Simulation dock; Clear all there puts the rail right.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::ModelView</name>
    <message>
        <source>Identify or autotune the rail to see its model, its fit and its Bode plot.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Identified model&lt;/b&gt; (G = K / (s (tau s + 1)), acceleration limited, Coulomb friction)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed gain K = %1 mm/s per code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time constant tau = %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>acceleration limit = %1 mm/s2 (mass %2 kg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coulomb friction = %1 mm/s2 (%2 N)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fit on held-out velocity (NRMSE) = &lt;b&gt;%1 %&lt;/b&gt;; on the fitted part %2 %; on position %3 % (flattering: position integrates)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>experiment: %1 s of machine time, at most %2 mm from the start, back within %3 counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Margins&lt;/b&gt;: gain %1 dB at %2 rad/s; phase %3 deg at %4 rad/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>infinite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|L| (dB)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>phase (deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frequency (rad/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open loop with the profile&apos;s engineered gains (Kp %1, Ki %2, Kd %3):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Design&lt;/b&gt; (SIMC, closed-loop time constant %1 ms, delay %2 ms): Kp %3, Ki %4, Kd %5; planning acceleration %6 mm/s2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Prediction (on the model, before applying) against measurement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>overshoot predicted (counts)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>settling +-1 count predicted (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine time of the whole autotune: %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Autotune passed&lt;/b&gt;: the tuned gains are in the step test&apos;s boxes; Save tuned profile... keeps them in a profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autotune failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::PlotPanel</name>
    <message>
        <source>Export PNG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rolling window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>setpoint</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DAC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>following error (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>drive (DAC code)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::PlotterPanel</name>
    <message>
        <source>Plotter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Origin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog up (+y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog down (-y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog left (-x)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog right (+x)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> steps/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object: %1 points (at most 300 per object)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::ProgramLibraryPanel</name>
    <message>
        <source>Folder: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder: %1 (not created yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 bytes, no comment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not served: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Comment or size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open in the editor</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::ProgramPanel</name>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start from the selected block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A program this large is shown read-only: edit it in a text editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saves atomically: a crash never leaves half a file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 lines: too large to edit here, shown read-only. Click a line to select its block.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loading %1 (%2 MB)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No program is selected: there is no file to save to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::RailView</name>
    <message>
        <source>left end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right end</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::RunControls</name>
    <message>
        <source>Cycle start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed hold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Single block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed override -10 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed override +10 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed override 100 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed override %1 %</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::RunOverlay</name>
    <message>
        <source>Rise time 10-90 % (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settling time 2 % (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settling time +-1 count (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Overshoot (%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak time (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steady-state error (counts)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IAE (mm.s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ITAE (mm.s2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ISE (mm2.s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Following error max (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Following error RMS (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time saturated (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not reached</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time from the step (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>displacement (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::SelectFileDialog</name>
    <message>
        <source>Select</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::SimulationPanel</name>
    <message>
        <source>stuck encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>amplifier trip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>torn counter reads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lost counts above %1 counts/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cable slip %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>switch noise %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>late ticks up to %1 ms (p %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faults of the simulated rail, for teaching and rehearsal. They act at once; Clear all puts the rail right (acknowledge any alarm after).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stuck encoder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Amplifier trip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Torn counter reads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lost counts above (counts/s, 0 = off):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cable slip (fraction):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch noise (probability per read):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Late servo ticks, up to (ms):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Late tick probability:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear all</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::StartScreen</name>
    <message>
        <source>Didactic D.N.C. system for the automatic rail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>University of São Paulo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polytechnic School</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Numerical Control for the robot&apos;s rail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Original design, 1996. Rebuilt and finished as trilho.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Machine:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Robot rail (1996)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DC-motor XY table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stepper XY plotter</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::TermsView</name>
    <message>
        <source>What if: the same run with other gains</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ki</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kff</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs the recorded test again from the same start with these gains and adds it to the overlay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PWM (%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DAC codes from 128</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This run has no loop terms (a trace of a program): record a step test to see them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run a step test, then choose its column in the table.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>FF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sum before the clamp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>drive written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Tick %1&lt;/b&gt;, t = %2 s, period T = %3 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>e[k] = r[k] - y[k] = %1 - %2 = &lt;b&gt;%3 mm&lt;/b&gt; (%4 counts)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P = Kp e = %1 x %2 = %3 %; I = %4 %; FF = Kff v_ref = %5 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>u = P + I + FF = &lt;b&gt;%1 %&lt;/b&gt; -&gt; clamp -&gt; %2 % -&gt; PWM written %3 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The 1996 law: V[k] = floor(128 + Kp e[k] + (Kd / T) (e[k] - e[k-1]) + Ki sum(e) + 0.5), T in ms, clamped by M = F / 100</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kp e = %1 x %2 = %3; (Kd / T) (e[k] - e[k-1]) = (%4 / %5) x (%6 - %7) = %8; Ki sum(e) = %9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V = floor(128 + %1 + 0.5) = %2 -&gt; written &lt;b&gt;%3&lt;/b&gt;%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (clamped: saturated)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P = Kp e = %1 x %2 = %3 codes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I[k] = I[k-1] + Ki T e[k] = %1 codes (Ki = %2; held while the output is saturated: anti-windup)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>D = -Kd dy/dt (on the measurement, filtered: no kick when the setpoint jumps) = -%1 x %2 = %3 codes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>FF = (v_ref + tau a_ref) x 127 / v_max + Kd v_ref = %1 codes (v_ref = %2 mm/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>u = P + I + D + FF = &lt;b&gt;%1 codes&lt;/b&gt; -&gt; clamp and slew limit -&gt; %2 -&gt; DAC = round(128 + u + carried fraction) = &lt;b&gt;%3&lt;/b&gt;%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (saturated)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::WorkbenchWindow</name>
    <message>
        <source>Tuning workbench: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step test (simulated plant, virtual time)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Amplitude (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The sign is the direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed (% of rapid)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>100 %: a step at the rapid speed; below: a ramp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control law</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Engineered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Classic (1996)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Period (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The 1996 law ran at 10 ms: its gains are per tick, so at 1 ms they act ten times harder (a lesson, not a setting)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ki</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kff</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mass factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The plant&apos;s moving mass times this; the loop is not told</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1996 law against engineered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The same move with the 1996 law at its 10 ms and its gains, and with the engineered law</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identification and autotune</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identify the plant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At most 3 s of machine time, within 100 mm, back to the start within a count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autotune</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identify, design (SIMC), predict, then verify with a 10 mm step and a 1000 mm move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save tuned profile...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save run...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load run...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Responses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P, I, D terms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1996</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>engineered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2, %3 mm at %4 ms, mass x%5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running in virtual time...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1 done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1 stopped: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>what if (from run %1): %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identified: fit %1 % on held-out velocity.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autotune passed in %1 s of machine time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autotune failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the run has no samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No run is selected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run records (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1 and %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run records and traces (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save tuned profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine profiles (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot save &apos;%1&apos;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1: trilho-cli run --machine %1 uses it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::XyMainWindow</name>
    <message>
        <source>MANUAL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AUTOMATIC - ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HOMING</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RUNNING</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DWELL</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PAUSED</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ALARM</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E-STOP LATCHED</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open program...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E&amp;xit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Manual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connection...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the pen lifts and the carriage runs to the origin sensors, where both axes are zeroed (0, 0).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the DC table has no home switch: its origin is where it stood at power-on, and nothing moves.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic homes the machine first: %1 Go on?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home: stop the machine (or reset the E-stop, acknowledge the alarm) first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Home the machine? %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cycle start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1? %2The machine travels at full speed from (%3, %4) mm to the program&apos;s start, then runs it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its position is not known, so it homes first: %1 </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code programs (*.G *.g)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Block N%1, line %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 at %2 bit/s: %3 - packets %4, RESENDs %5, timeouts %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>link up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LINK LOST</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated machine (no hardware)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Board on a serial port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the machine before changing the connection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>trilho - %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic (home)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cycle start (F5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold (F6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume (F7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop (F8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E-STOP (Pause, F1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset E-stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acknowledge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No program loaded</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>trilho::ui::XyPlots</name>
    <message>
        <source>x set point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y set point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position (mm)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed (mm/s)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
