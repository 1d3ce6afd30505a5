/* trilho's plotter firmware for seed 001's board: an Arduino UNO (ATmega328P at 16 MHz), plain
 * avr-libc (no Arduino core), issue 32 item 7. It speaks seed 001's protocol (3.3, tables 6 and
 * 7; docs/protocols.md A): 6-byte packets at 57600 bit/s 8N1, command hiX loX hiY loY checksum
 * (the sum of the first five bytes in one byte), one byte answered a packet. It stores an
 * object of up to 300 points (5 bytes each, 1500 bytes of the UNO's 2048), plots it on END with
 * annex C's Bresenham or annex G's float line (this image's PLOTTER_LINE_FLOAT: two images of
 * this one source, plotter-bresenham and plotter-float; README.md says why), one step event per
 * two SPEED microseconds (SPEED is the step clock's half period in us, docs/seeds.md) plus the
 * time the chip takes to compute it, and homes on the two origin sensors.
 *
 * Where the seed is silent it does what trilho's C++ emulator of this board does
 * (hal/emulator/plotter_firmware.cpp), so trilho's host sees the same board:
 * - a 301st point is answered RESEND and not stored;
 * - bytes of one packet more than 50 ms apart: the partial packet is stale and restarts with the
 *   new byte; a partial packet 2 s old is dropped and answered RESEND (the seed's timeout);
 * - END while plotting is ignored (the host waits for DONE); points sent while plotting are
 *   stored and plotted with the object; REQUEST and SPEED are answered at once;
 * - each segment starts where the head is (the float line's one-step shortfall is made up by
 *   the next segment); the float line's first event (0, 0) takes an event's time;
 * - the pen's solenoid is given 50 ms to settle whenever it switches;
 * - SPEED below 500 us runs at 500 us (1000 events a second, the profile's pull-out rate);
 * - a jog (UP, DOWN, LEFT, RIGHT) is 10 steps (1 mm at 0.1 mm a step) with the pen up,
 *   answered with its own byte when done;
 * - homing (ORIGEM): pen up, off the sensors if on one, then towards the origin at 400 events
 *   a second until both read; after 3100 steps without them it gives up.
 * One difference, chosen: when homing gives up the board does not answer ORIGIN_OK (the
 * emulator does): table 7 has no error answer, and "ORIGIN_OK" would say the head is at the
 * origin when it is not; the host's deadline then fails the job with a plain reason.
 *
 * Pins (the UNO's digital pin numbers in brackets):
 *   PD4 (4) X step, PD7 (7) Y step: one rising edge per step (not the CNC shield's PD2 / PD3:
 *   those are INT0 / INT1, and simavr polls a low INT pin every cycle, enabled or not, which
 *   made the simulation 20 times slower: 161 M port reads in 5.7 board seconds);
 *   PD5 (5) X direction, PD6 (6) Y direction: high = positive (away from the origin);
 *   PB4 (12) pen solenoid: high = pen down;
 *   PB1 (9) X origin sensor, PB2 (10) Y origin sensor: inputs with pull-ups, LOW when the
 *   sensor sees its flag (a cut cable reads high: never "at the origin", so homing gives up).
 * Timer 1 runs free at 2 MHz (0.5 us, the clock of every wait and timeout); Timer 2 interrupts
 * every 100 us only to wake the chip from idle sleep, so the receiver is polled at least once
 * per 100 us (a byte takes 174 us on the line; the UART holds two and a third in its shift
 * register). */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <stdint.h>
#include <util/delay.h>

#ifndef PLOTTER_LINE_FLOAT
#define PLOTTER_LINE_FLOAT 0
#endif

/* Table 7. */
enum {
    CMD_REQUEST = 114,
    CMD_LINE = 108,
    CMD_MOVE = 109,
    CMD_END = 101,
    CMD_ORIGIN = 111,
    CMD_SPEED = 115,
    CMD_UP = 56,
    CMD_LEFT = 52,
    CMD_DOWN = 50,
    CMD_RIGHT = 54
};
enum {
    REPLY_REQUEST_OK = 107,
    REPLY_RESEND = 114,
    REPLY_NEXT = 110,
    REPLY_DONE = 100,
    REPLY_ORIGIN_OK = 111,
    REPLY_SPEED_OK = 115
};

#define MAX_POINTS 300                    /* 1500 bytes of RAM, 5 a point (seed 001 3.3) */
#define TICKS_PER_US 2UL                  /* Timer 1 at F_CPU / 8 */
#define RECEIVER_TIMEOUT_TICKS 4000000UL  /* 2 s: a partial packet is dropped, RESEND */
#define INTER_BYTE_GAP_TICKS 100000UL     /* 50 ms: a longer gap makes a partial packet stale */
#define PEN_SETTLE_TICKS 100000UL         /* 50 ms for the solenoid (trilho's chosen figure) */
#define MIN_HALF_PERIOD_US 500U           /* 1000 events/s, the motors' pull-out rate */
#define DEFAULT_SPEED 1111U               /* 450 events/s: trilho's profile default */
#define HOMING_HALF_PERIOD_US 1250U       /* 400 events/s */
#define HOMING_LIMIT_STEPS 3100L          /* the 300 mm axis plus 10 mm, at 0.1 mm a step */
#define JOG_STEPS 10                      /* 1 mm */
#define NAP_MIN_TICKS 240UL               /* sleep only when more than 120 us are left */

struct point {
    uint8_t command; /* CMD_LINE or CMD_MOVE */
    uint16_t x, y;   /* steps from the origin */
};

static struct point points[MAX_POINTS];
static volatile uint16_t point_count;
static uint16_t speed = DEFAULT_SPEED;
/* The steps sent, from the origin (from power-on until homed); global so a test reads them. */
int32_t head_x, head_y;
static uint8_t pen_known, pen_down;
static uint8_t dir_x_positive = 2, dir_y_positive = 2; /* 2: not written yet */
static uint8_t busy;                                   /* plotting, homing or jogging */

static uint8_t packet[6];
static uint8_t have;
static uint32_t last_byte_at, partial_since;

/* Counters a test can read (the ELF's symbols): what the board did. */
volatile uint16_t stat_packets, stat_bad_checksums, stat_resends, stat_stale, stat_refused,
    stat_objects;

static volatile uint16_t timer1_overflows;

ISR(TIMER1_OVF_vect) {
    ++timer1_overflows;
}

/* Wakes the chip from idle sleep, nothing else. */
EMPTY_INTERRUPT(TIMER2_COMPA_vect);

/* Timer 1's count extended to 32 bits, 0.5 us a tick (wraps every 35 minutes: every interval
 * is taken as a difference). */
static uint32_t now_ticks(void) {
    const uint8_t sreg = SREG;
    cli();
    uint16_t high = timer1_overflows;
    const uint16_t low = TCNT1;
    if ((TIFR1 & _BV(TOV1)) && low < 0x8000U) ++high; /* overflowed, not yet counted */
    SREG = sreg;
    return ((uint32_t)high << 16) | low;
}

static void reply(uint8_t byte) {
    while (!(UCSR0A & _BV(UDRE0))) {
    }
    UDR0 = byte;
}

static void handle(uint8_t command, uint16_t x, uint16_t y);

/* One byte from the line: the packet's next byte; a complete packet is checked and handled. */
static void take_byte(uint8_t byte, uint32_t now) {
    if (have > 0 && now - last_byte_at > INTER_BYTE_GAP_TICKS) {
        ++stat_stale; /* a byte of that packet was lost: start again with this one */
        have = 0;
    }
    if (have == 0) partial_since = now;
    last_byte_at = now;
    packet[have++] = byte;
    if (have < 6) return;
    have = 0;
    const uint8_t sum = (uint8_t)(packet[0] + packet[1] + packet[2] + packet[3] + packet[4]);
    const uint8_t c = packet[0];
    const uint8_t known = c == CMD_REQUEST || c == CMD_LINE || c == CMD_MOVE || c == CMD_END ||
                          c == CMD_ORIGIN || c == CMD_SPEED || c == CMD_UP || c == CMD_LEFT ||
                          c == CMD_DOWN || c == CMD_RIGHT;
    if (!known || sum != packet[5]) {
        ++stat_bad_checksums;
        ++stat_resends;
        reply(REPLY_RESEND);
        return;
    }
    ++stat_packets;
    handle(c, (uint16_t)((packet[1] << 8) | packet[2]), (uint16_t)((packet[3] << 8) | packet[4]));
}

/* The line, polled: every byte the UART holds, then the receiver's 2 s timeout. Called from
 * the main loop and from every wait, so the line is served while the board plots. */
static void poll_line(void) {
    while (UCSR0A & _BV(RXC0)) {
        const uint8_t byte = UDR0;
        take_byte(byte, now_ticks());
    }
    if (have > 0 && now_ticks() - partial_since >= RECEIVER_TIMEOUT_TICKS) {
        have = 0;
        ++stat_resends;
        reply(REPLY_RESEND);
    }
}

/* Waits ticks (0.5 us each) from now, serving the line; sleeps (idle: timers and UART run) in
 * Timer 2's 100 us naps while more than NAP_MIN_TICKS are left. */
static void wait_ticks(uint32_t ticks) {
    const uint32_t start = now_ticks();
    for (;;) {
        poll_line();
        const uint32_t elapsed = now_ticks() - start;
        if (elapsed >= ticks) return;
        if (ticks - elapsed > NAP_MIN_TICKS) {
            sleep_enable();
            sei();
            sleep_cpu();
            sleep_disable();
        }
    }
}

static uint16_t half_period_us(void) {
    return speed < MIN_HALF_PERIOD_US ? MIN_HALF_PERIOD_US : speed;
}

static void set_pen(uint8_t down) {
    if (pen_known && pen_down == down) return;
    if (down)
        PORTB |= _BV(PB4);
    else
        PORTB &= (uint8_t)~_BV(PB4);
    pen_down = down;
    pen_known = 1;
    wait_ticks(PEN_SETTLE_TICKS);
}

/* One step event (annex C's put_Pixel, 3.1.3.3's executaPassos): each axis -1, 0 or +1. The
 * direction pins first, then the step edge, SPEED us, the falling edge, SPEED us. */
static void step_event(int8_t dx, int8_t dy, uint16_t half_us) {
    uint8_t changed = 0;
    if (dx != 0 && dir_x_positive != (dx > 0)) {
        dir_x_positive = dx > 0;
        if (dir_x_positive)
            PORTD |= _BV(PD5);
        else
            PORTD &= (uint8_t)~_BV(PD5);
        changed = 1;
    }
    if (dy != 0 && dir_y_positive != (dy > 0)) {
        dir_y_positive = dy > 0;
        if (dir_y_positive)
            PORTD |= _BV(PD6);
        else
            PORTD &= (uint8_t)~_BV(PD6);
        changed = 1;
    }
    if (changed) _delay_us(1); /* the driver's direction set-up time before the edge */
    const uint8_t pulse = (uint8_t)((dx ? _BV(PD4) : 0) | (dy ? _BV(PD7) : 0));
    PORTD |= pulse;
    wait_ticks(half_us * TICKS_PER_US);
    PORTD &= (uint8_t)~pulse;
    wait_ticks(half_us * TICKS_PER_US);
    head_x += dx;
    head_y += dy;
}

#if PLOTTER_LINE_FLOAT
/* Annex G's drawLine_Float, as printed, but signed (the printed unsigned x1 makes x - x1 wrap
 * on a line towards -x) and in 32 bits (the wire's 16-bit coordinates overflow an int's
 * differences): single-precision float, (int) truncating, the first event (0, 0), the line
 * stopping one step short on its major axis. */
static void draw_line(int32_t x1, int32_t y1, int32_t x2, int32_t y2, uint16_t half_us) {
    const int32_t dx = x2 - x1;
    const int32_t dy = y2 - y1;
    int32_t old_x = x1, old_y = y1;
    if (dx == 0 && dy == 0) return;
    if ((dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy)) {
        const int8_t inc = dx < 0 ? -1 : 1;
        const float dydx = (float)dy / (float)dx;
        for (int32_t x = x1; x != x2; x += inc) {
            const int32_t y = (int32_t)(dydx * (float)(x - x1) + (float)y1);
            step_event((int8_t)(x - old_x), (int8_t)(y - old_y), half_us);
            old_x = x;
            old_y = y;
        }
    } else {
        const int8_t inc = dy < 0 ? -1 : 1;
        const float dxdy = (float)dx / (float)dy;
        for (int32_t y = y1; y != y2; y += inc) {
            const int32_t x = (int32_t)(dxdy * (float)(y - y1) + (float)x1);
            step_event((int8_t)(x - old_x), (int8_t)(y - old_y), half_us);
            old_x = x;
            old_y = y;
        }
    }
}
#else
/* Annex C's drawLine_Bresenham: the major axis steps every event, the decision d says when
 * the minor one does too (d <= 0: E, else NE); in 32 bits for the wire's 16-bit coordinates. */
static void draw_line(int32_t x1, int32_t y1, int32_t x2, int32_t y2, uint16_t half_us) {
    const int32_t dx = x2 >= x1 ? x2 - x1 : x1 - x2;
    const int32_t dy = y2 >= y1 ? y2 - y1 : y1 - y2;
    const int8_t inc_x = x2 >= x1 ? 1 : -1;
    const int8_t inc_y = y2 >= y1 ? 1 : -1;
    if (dx >= dy) {
        int32_t d = 2 * dy - dx;
        const int32_t inc_e = 2 * dy, inc_ne = 2 * (dy - dx);
        while (x1 != x2) {
            if (d <= 0) {
                d += inc_e;
                step_event(inc_x, 0, half_us);
            } else {
                d += inc_ne;
                step_event(inc_x, inc_y, half_us);
                y1 += inc_y;
            }
            x1 += inc_x;
        }
    } else {
        int32_t d = 2 * dx - dy;
        const int32_t inc_e = 2 * dx, inc_ne = 2 * (dx - dy);
        while (y1 != y2) {
            if (d <= 0) {
                d += inc_e;
                step_event(0, inc_y, half_us);
            } else {
                d += inc_ne;
                step_event(inc_x, inc_y, half_us);
                x1 += inc_x;
            }
            y1 += inc_y;
        }
    }
}
#endif

static uint8_t at_origin_x(void) {
    return !(PINB & _BV(PB1));
}
static uint8_t at_origin_y(void) {
    return !(PINB & _BV(PB2));
}

/* ORIGEM: 1 when both sensors read (the counters then 0), 0 when it gave up. */
static uint8_t home(void) {
    set_pen(0);
    uint8_t backing_off = 1;
    for (int32_t steps = 0;; ++steps) {
        const uint8_t ox = at_origin_x(), oy = at_origin_y();
        if (backing_off && !ox && !oy) backing_off = 0;
        if (!backing_off && ox && oy) {
            head_x = head_y = 0;
            return 1;
        }
        if (steps >= HOMING_LIMIT_STEPS) return 0;
        if (backing_off) /* started on a sensor: step off it to find its edge again */
            step_event(ox ? 1 : 0, oy ? 1 : 0, HOMING_HALF_PERIOD_US);
        else
            step_event(ox ? 0 : -1, oy ? 0 : -1, HOMING_HALF_PERIOD_US);
    }
}

static void plot_object(void) {
    /* point_count may grow while plotting: points sent meanwhile are stored and plotted. */
    for (uint16_t i = 0; i < point_count; ++i) {
        const struct point p = points[i];
        set_pen(p.command == CMD_LINE);
        draw_line(head_x, head_y, p.x, p.y, half_period_us());
    }
    point_count = 0;
    ++stat_objects;
}

static void handle(uint8_t command, uint16_t x, uint16_t y) {
    switch (command) {
        case CMD_REQUEST:
            reply(REPLY_REQUEST_OK);
            return;
        case CMD_SPEED:
            speed = x < 1 ? 1 : x;
            reply(REPLY_SPEED_OK);
            return;
        case CMD_LINE:
        case CMD_MOVE:
            if (point_count >= MAX_POINTS) {
                ++stat_refused; /* no room: not taken, the host must not lose it silently */
                ++stat_resends;
                reply(REPLY_RESEND);
                return;
            }
            points[point_count].command = command;
            points[point_count].x = x;
            points[point_count].y = y;
            ++point_count;
            reply(REPLY_NEXT);
            return;
        default:
            break;
    }
    if (busy) return; /* END, ORIGEM, a jog while moving: the host waits for the answer */
    busy = 1;
    switch (command) {
        case CMD_END:
            plot_object();
            reply(REPLY_DONE);
            break;
        case CMD_ORIGIN:
            if (home()) reply(REPLY_ORIGIN_OK);
            break;
        default: { /* a jog */
            const int8_t sx = command == CMD_RIGHT ? 1 : command == CMD_LEFT ? -1 : 0;
            const int8_t sy = command == CMD_UP ? 1 : command == CMD_DOWN ? -1 : 0;
            set_pen(0);
            draw_line(head_x, head_y, head_x + sx * JOG_STEPS, head_y + sy * JOG_STEPS,
                      half_period_us());
            reply(command);
            break;
        }
    }
    busy = 0;
}

int main(void) {
    DDRD = _BV(PD4) | _BV(PD7) | _BV(PD5) | _BV(PD6);
    DDRB = _BV(PB4);
    PORTB = _BV(PB1) | _BV(PB2); /* the sensors' pull-ups; the pen up */
    /* 57600 bit/s 8N1: U2X, UBRR 34 (57143 bit/s, -0.8 %, as the Arduino core sets it). */
    UCSR0A = _BV(U2X0);
    UBRR0H = 0;
    UBRR0L = 34;
    UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);
    UCSR0B = _BV(RXEN0) | _BV(TXEN0);
    TCCR1A = 0;
    TCCR1B = _BV(CS11); /* free-running, F_CPU / 8 = 2 MHz */
    TIMSK1 = _BV(TOIE1);
    TCCR2A = _BV(WGM21); /* CTC, F_CPU / 64 = 250 kHz, 25 counts = 100 us */
    OCR2A = 24;
    TCCR2B = _BV(CS22);
    TIMSK2 = _BV(OCIE2A);
    set_sleep_mode(SLEEP_MODE_IDLE);
    sei();
    for (;;)
        wait_ticks(NAP_MIN_TICKS * 4); /* serves the line; handle() runs from there */
}
