/*
 * trilho's table firmware (issue 32 item 6): seed 004's ATmega128 board at 8 MHz, its pins
 * as the seed wires them, speaking trilho's protocol (docs/protocols.md B): the 4-byte set
 * point (hiX loX hiY loY, whole mm) in, the 11-byte answer out (ACK in position, NAK outside
 * the table, CAN when the drives were cut). The motion is what trilho's C++ emulator of this
 * board runs (hal/emulator/table_firmware.cpp over core/xy/dc_table_motion.cpp, the profile
 * resources/machines/xy_dc_table.json): the synchronized trapezoid along the line, the
 * engineered law per axis (feed-forward + PI with anti-windup, settling and in-position
 * phases), both axes together every 5 ms, the in-position check, following error, over-current
 * and the encoder plausibility check. README.md lists what differs from the seed's program and
 * why.
 *
 * Pins (seed 004, annex 7):
 *   PB5 OC1A / PB6 OC1B: x / y PWM, Timer 1 fast PWM mode 14, TOP = ICR1 = 247 (32.3 kHz);
 *   PC0 / PC1: x / y direction bit (1 = backwards);
 *   PE4 INT4 / PE6 INT6: x / y encoder channel A, one rising edge per count;
 *   PE5 INT5 / PE7 INT7: x / y over-current comparator (rising: tripped);
 *   PE0 RXD0 / PE1 TXD0: the host's line, 9600 bit/s 8N1.
 * Added to the seed's wiring (the seed counts one channel and takes the sign from its set
 * point, which miscounts every count an axis makes against its move's direction, as the
 * engineered law's corrections do):
 *   PE2 / PE3: x / y encoder channel B, read at channel A's rising edge (high = forwards).
 *
 * Arithmetic: single-precision float (avr-libc's; avr-gcc's double is the same 32 bits). The
 * law and the planner are the emulator's, written in mm, mm/s and seconds; float keeps them
 * as written, so this file can be read line by line against the C++ (the point of the
 * exercise), and its 24 bits hold 300 mm to 0.02 um. The cost is time: a period's body takes
 * up to 2.5 ms of the 5 ms (soft float, about 150 cycles a multiply), which the board has; the
 * receiver is polled between its parts (poll_rx). Fixed point would buy time the board does not
 * need and lose the line-by-line match. Time itself is counted in integers (ticks), so nothing
 * drifts.
 */
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>
#include <math.h>
#include <stdint.h>

/* ---- the machine (resources/machines/xy_dc_table.json; chosen figures marked there) ---- */
#define PERIOD_S 0.005f        /* dcTable.samplePeriodS */
#define LOOP_MS 5              /* the same, in 1 ms ticks */
#define RAPID_MM_S 150.0f      /* motion.rapidSpeedMmS (seed 004: vel_max) */
#define ACCEL_MM_S2 300.0f     /* motion.accelerationMmS2 (seed 004: acel) */
#define CLAMP_PERCENT 50.0f    /* dcTable.pwmClampPercent (seed 004: max = 50) */
#define DUTY_MAX 247           /* dcTable.pwmDutyMax (seed 004: ICR1 = 247) */
#define FOLLOWING_MM 5.0f      /* dcTable.followingErrorLimitMm */
#define WINDOW_MM 0.05f        /* dcTable.inPositionWindowMm */
#define SOFT_MAX_MM 300        /* limits.x/y.softMaxMm, whole mm (softMinMm is 0) */
#define IN_POSITION_TICKS 4    /* kInPositionTimeS 0.02 s: both axes in the window 4 periods */
#define SETTLE_TIMEOUT_S 3.0f  /* kSettleTimeoutS: a profile that ended must settle within */
#define STALL_MM 1.0f          /* kEncoderStallMm: travel the model makes with no count */
#define STALL_DEAD_BAND 1.5f   /* kStallDeadBandFriction */
#define MIN_MASS 0.1f          /* kMinMassFactor: slowing down, as the lightest payload */
#define SPEED_UP_MASS 2.0f     /* kSpeedUpInertia: speeding up, as twice the inertia */
#define SETTLE_BOOST 4.0f      /* kSettleIntegralBoost (dc_axis_loop.cpp) */
#define GAP_US 50000UL         /* TableFirmware::kInterByteGapS: the two bytes of a coordinate */

/* Per axis: mm per count = mmPerTurn x radPerCount / (2 pi); tau, friction, no-load speed,
   the engineered gains (kp %/mm, ki %/(mm.s), kff %/(mm/s)). */
typedef struct {
    float mmPerCount, tau, coulomb, noLoad, kp, ki, kff;
} AxisParams;
static const AxisParams kAxis[2] = {
    {2.12f * 0.314f / (2.0f * (float)M_PI), 0.03f, 3.0f, 400.0f, 14.0f, 40.0f, 0.25f},
    {2.00f * 0.314f / (2.0f * (float)M_PI), 0.03f, 3.0f, 400.0f, 14.0f, 40.0f, 0.25f},
};

/* ---- the protocol (docs/protocols.md B) ---- */
#define ACK 0x06
#define NAK 0x15
#define CAN 0x18
#define ANSWER_BYTES 11

/* ---- counters the harness and the tests read by name (trilho-device prints them) ---- */
volatile uint32_t stat_set_points;  /* complete set points received */
volatile uint32_t stat_reached;     /* ACK sent */
volatile uint32_t stat_refused;     /* NAK sent */
volatile uint32_t stat_cut;         /* CAN sent */
volatile uint32_t stat_stale;       /* partial coordinates dropped for a gap */
volatile uint32_t stat_ignored;     /* set points completed during a move (dropped) */
volatile uint32_t stat_started;     /* moves begun, repeats of the same set point included */
volatile uint8_t stat_last_fault;   /* why the last CAN: 3 following, 12 settle, 16 encoder,
                                       17 over-current (trilho's alarm codes) */
volatile uint16_t run_x, run_y;     /* the set point begun last ((0, 0) at power-on) */
volatile uint8_t moves;             /* moves begun since power-on, mod 256 (in every answer) */
volatile uint8_t moving;            /* a set point runs: its answer is due */
volatile uint16_t stat_loop_us_max; /* the longest period's body, us (Timer 3's clock): it must
                                       stay under the receiver's 3 ms of buffer */

/* ---- time: Timer 3, CTC, 1 ms ---- */
static volatile uint32_t g_ms;       /* ms since power-on */
static volatile uint8_t g_loop_due;  /* periods of 5 ms due, not yet run */

ISR(TIMER3_COMPA_vect) {
    static uint8_t sub;
    ++g_ms;
    if (++sub >= LOOP_MS) {
        sub = 0;
        if (g_loop_due < 255) ++g_loop_due;
    }
}

/* Microseconds since power-on (wraps after 71 minutes; only differences are used). */
static uint32_t now_us(void) {
    uint8_t sreg = SREG;
    cli();
    uint32_t ms = g_ms;
    uint16_t t = TCNT3;               /* 1 us a count, 0..999 */
    if (ETIFR & (1 << OCF3A)) {       /* the compare came after cli(): not yet counted */
        ms += 1;
        t = TCNT3;
    }
    SREG = sreg;
    return ms * 1000UL + t;
}

/* ---- the encoders: channel A on INT4 / INT6, channel B on PE2 / PE3 ---- */
static volatile int16_t g_count[2]; /* counts from the power-on origin */

static volatile uint16_t g_edges[2]; /* every edge, either way (the calibration's pulsos) */

ISR(INT4_vect) {
    ++g_edges[0];
    if (PINE & (1 << PE2))
        ++g_count[0];
    else
        --g_count[0];
}
ISR(INT6_vect) {
    ++g_edges[1];
    if (PINE & (1 << PE3))
        ++g_count[1];
    else
        --g_count[1];
}

/* ---- the drives: Timer 1 fast PWM, and the over-current inputs ---- */
static volatile uint8_t g_over_current[2];

static void pwm_start(void) {
    /* Mode 14 (WGM13:10 = 1110), TOP = ICR1 = 247, no prescaler: 8 MHz / 248 = 32.3 kHz as the
       seed's config_pwm. The channels' pins start disconnected (COM1x = 0: PORTB's 0), so
       duty 0 is 0, not the one-clock spike fast PWM gives at OCR1x = 0. */
    TCCR1A = (1 << WGM11);
    ICR1 = DUTY_MAX;
    OCR1A = 0;
    OCR1B = 0;
    TCCR1B = (1 << WGM13) | (1 << WGM12) | (1 << CS10);
}

/* The over-current comparator cuts both channels at once, as the seed's handlers do (Timer 1
   drives both): its clock stopped and the pins back to PORTB's 0. The period reads the flag. */
ISR(INT5_vect) {
    TCCR1B = 0;
    TCCR1A = 0;
    g_over_current[0] = 1;
}
ISR(INT7_vect) {
    TCCR1B = 0;
    TCCR1A = 0;
    g_over_current[1] = 1;
}

/* One axis' drive: signed percent, floored to whole duty steps (seed: OCR1x = floor(u /
   0.405)), the sign on the direction bit. The pin is high OCR1x + 1 clocks of 248, so
   OCR1x = duty - 1 puts duty / 248 on it (the emulator's duty / 247 within 0.4 % of itself);
   duty 0 disconnects the pin. */
static void write_drive(uint8_t k, float percent) {
    float d = floorf(fabsf(percent) * (float)DUTY_MAX / 100.0f);
    if (d > DUTY_MAX) d = DUTY_MAX;
    if (!(d >= 0.0f)) d = 0.0f;
    const uint8_t duty = (uint8_t)d;
    const uint8_t com = k == 0 ? (1 << COM1A1) : (1 << COM1B1);
    const uint8_t bit = (uint8_t)(1 << k);
    /* Not while Timer 1 is stopped by an over-current: the period clears that first. */
    if (TCCR1B == 0) return;
    if (percent < 0.0f)
        PORTC |= bit;
    else
        PORTC &= (uint8_t)~bit;
    if (duty == 0) {
        TCCR1A &= (uint8_t)~com;
        return;
    }
    if (k == 0)
        OCR1A = duty - 1;
    else
        OCR1B = duty - 1;
    TCCR1A |= com;
}

/* ---- the line: UART0 polled for reception, a ring drained by UDRE0's interrupt ---- */
static volatile uint8_t g_tx[64];
static volatile uint8_t g_tx_head, g_tx_tail;

ISR(USART0_UDRE_vect) {
    if (g_tx_head == g_tx_tail) {
        UCSR0B &= (uint8_t)~(1 << UDRIE0);
        return;
    }
    UDR0 = g_tx[g_tx_tail];
    g_tx_tail = (uint8_t)((g_tx_tail + 1) & 63);
}

volatile uint32_t stat_answers_dropped; /* whole answers not sent: the line was full */

/* Room in the ring, bytes (one slot stays empty to tell full from empty). */
static uint8_t tx_room(void) {
    return (uint8_t)(63 - ((g_tx_head - g_tx_tail) & 63));
}

static void send_byte(uint8_t b) {
    g_tx[g_tx_head] = b;
    g_tx_head = (uint8_t)((g_tx_head + 1) & 63);
    UCSR0B |= (1 << UDRIE0);
}

/* ---- the receiver: UART0 polled (RXC0) into a ring, each byte with its time. UDR0 holds two
   bytes and the shift register a third (3.1 ms at 9600 bit/s): poll_rx() runs in the main loop
   and between the parts of a period's body (which takes up to about 2.5 ms whole), so the
   receiver is never left unpolled longer than the idle millisecond and one part (1.6 ms
   measured, stat_rx_gap_us_max). ---- */
#define RX_RING 16
static uint8_t g_ring[RX_RING];
static uint32_t g_ring_us[RX_RING];
static uint8_t g_ring_head, g_ring_tail;
static uint32_t g_last_poll_us;
volatile uint16_t stat_rx_gap_us_max; /* the longest time the receiver went unpolled, us */
volatile uint32_t stat_rx_ring_full;  /* bytes dropped for a full ring (none expected) */

static void poll_rx(void) {
    const uint32_t now = now_us();
    const uint32_t gap = now - g_last_poll_us;
    g_last_poll_us = now;
    if (gap > stat_rx_gap_us_max) stat_rx_gap_us_max = gap > 65535UL ? 65535U : (uint16_t)gap;
    while (UCSR0A & (1 << RXC0)) {
        const uint8_t b = UDR0;
        const uint8_t next = (uint8_t)((g_ring_head + 1) % RX_RING);
        if (next == g_ring_tail) {
            ++stat_rx_ring_full;
            continue;
        }
        g_ring[g_ring_head] = b;
        g_ring_us[g_ring_head] = now;
        g_ring_head = next;
    }
}

/* ---- the planner: SyncTrapezoid over Trapezoid::restToRest (core/motion) ---- */
typedef struct {
    float start[2], dir[2]; /* mm; unit direction (0, 0 for a null move) */
    float t[3], a[3];       /* segments: start time s, acceleration mm/s2 (along the path) */
    float p0[3], v0[3];     /* their start position mm and speed mm/s */
    uint8_t n;              /* segments (0: a null move) */
    float duration;         /* s */
    float length;           /* mm */
} Plan;

static Plan g_plan;

static void plan_line(float x0, float y0, float x1, float y1) {
    Plan* p = &g_plan;
    const float dx = x1 - x0, dy = y1 - y0;
    p->start[0] = x0;
    p->start[1] = y0;
    p->length = sqrtf(dx * dx + dy * dy);
    p->n = 0;
    p->duration = 0.0f;
    p->dir[0] = p->dir[1] = 0.0f;
    if (p->length == 0.0f) return;
    p->dir[0] = dx / p->length;
    p->dir[1] = dy / p->length;
    /* Along the path, the largest speed and acceleration that keep each axis within its own. */
    float speed = INFINITY, accel = INFINITY;
    for (uint8_t k = 0; k < 2; ++k) {
        const float share = fabsf(p->dir[k]);
        if (share == 0.0f) continue;
        if (RAPID_MM_S / share < speed) speed = RAPID_MM_S / share;
        if (ACCEL_MM_S2 / share < accel) accel = ACCEL_MM_S2 / share;
    }
    poll_rx();
    const float dist = p->length;
    const float peak = sqrtf(accel * dist);
    float dur[3], acc[3];
    if (peak <= speed) { /* triangular */
        p->n = 2;
        dur[0] = peak / accel, acc[0] = accel;
        dur[1] = peak / accel, acc[1] = -accel;
    } else {
        const float ramp = speed * speed / (2.0f * accel);
        p->n = 3;
        dur[0] = speed / accel, acc[0] = accel;
        dur[1] = (dist - 2.0f * ramp) / speed, acc[1] = 0.0f;
        dur[2] = speed / accel, acc[2] = -accel;
        if (!(dur[1] > 0.0f)) { /* no cruise after all (rounding): Trapezoid drops it */
            dur[1] = dur[2];
            acc[1] = acc[2];
            p->n = 2;
        }
    }
    float t = 0.0f, pos = 0.0f, v = 0.0f;
    for (uint8_t i = 0; i < p->n; ++i) {
        p->t[i] = t, p->p0[i] = pos, p->v0[i] = v, p->a[i] = acc[i];
        pos += v * dur[i] + 0.5f * acc[i] * dur[i] * dur[i];
        v += acc[i] * dur[i];
        t += dur[i];
    }
    p->duration = t;
}

/* Position, speed and acceleration along the path at t (Trapezoid::at). */
static void plan_at(float t, float* s, float* v, float* a) {
    const Plan* p = &g_plan;
    if (p->n == 0 || t >= p->duration) {
        *s = p->length, *v = 0.0f, *a = 0.0f;
        return;
    }
    if (t <= 0.0f) {
        *s = 0.0f, *v = 0.0f, *a = p->a[0];
        return;
    }
    uint8_t i = 0;
    while (i + 1 < p->n && t >= p->t[i + 1])
        ++i;
    const float tau = t - p->t[i];
    *s = p->p0[i] + p->v0[i] * tau + 0.5f * p->a[i] * tau * tau;
    *v = p->v0[i] + p->a[i] * tau;
    *a = p->a[i];
}

/* ---- the motion: DcTableMotion under the engineered law ---- */
enum { IDLE, MOVING, SETTLING };
enum { TRACKING, AXIS_SETTLING, IN_POSITION }; /* DcAxisLoop::Phase */
#define FAULT_NONE 0
#define FAULT_FOLLOWING 3
#define FAULT_SETTLE 12
#define FAULT_ENCODER 16
#define FAULT_OVER_CURRENT 17

static uint8_t g_phase = IDLE;
static uint16_t g_plan_ticks;    /* periods since the move began */
static uint8_t g_settle_ticks;   /* periods both axes have been in the window */
static uint16_t g_settling_for;  /* periods since the profile ended */
static float g_commanded[2];     /* the set point of the loops, mm */
static float g_cmd_v[2], g_cmd_a[2];
static int16_t g_counts[2];      /* the counts at the last period */
static float g_measured[2];      /* mm: the centre of the count */
static float g_drive[2];         /* the last drive written, signed % */
static float g_integral[2];      /* the PI's integral, mm.s */
static float g_model_v[2];       /* the encoder check's motor model, mm/s */
static float g_stall_mm[2];      /* mm the model ran since the count last changed */
static float g_since_count[2];   /* s since each axis' count last changed */
static uint8_t g_fault;
static uint8_t g_drives_on = 1;

static void read_encoders(int16_t counted[2]) {
    for (uint8_t k = 0; k < 2; ++k) {
        cli();
        const int16_t c = g_count[k];
        sei();
        counted[k] = (int16_t)(c - g_counts[k]);
        g_counts[k] = c;
        g_measured[k] = ((float)c + 0.5f) * kAxis[k].mmPerCount;
    }
}

static void cut(void) {
    g_drives_on = 0;
    for (uint8_t k = 0; k < 2; ++k) {
        g_model_v[k] = g_stall_mm[k] = g_since_count[k] = 0.0f;
        write_drive(k, 0.0f);
        g_drive[k] = 0.0f;
    }
    g_phase = IDLE;
}

static void raise_fault(uint8_t code) {
    if (g_fault == FAULT_NONE) g_fault = code;
    cut();
}

/* DcTableMotion::clearFault: the PWM again, hold where the table stands. */
static void clear_fault(void) {
    int16_t counted[2];
    g_fault = FAULT_NONE;
    cli();
    g_over_current[0] = g_over_current[1] = 0;
    pwm_start();
    sei();
    read_encoders(counted);
    for (uint8_t k = 0; k < 2; ++k) {
        g_commanded[k] = g_measured[k];
        g_cmd_v[k] = g_cmd_a[k] = 0.0f;
        g_integral[k] = 0.0f;
        g_drive[k] = 0.0f;
    }
    g_phase = IDLE;
    g_drives_on = 1;
}

/* DcTableMotion::checkEncoder: the drive ran the model's travel with no change of the count. */
static uint8_t check_encoder(uint8_t k, int16_t counted) {
    const AxisParams* a = &kAxis[k];
    const float u = g_drive[k];
    float over = fabsf(u) - STALL_DEAD_BAND * a->coulomb;
    if (over < 0.0f) over = 0.0f;
    const float target = over > 0.0f ? copysignf(over * a->noLoad / 100.0f, u) : 0.0f;
    float v = g_model_v[k];
    g_since_count[k] += PERIOD_S;
    if (counted != 0) {
        g_model_v[k] = (float)counted * a->mmPerCount / g_since_count[k];
        g_since_count[k] = 0.0f;
        g_stall_mm[k] = 0.0f;
        return 1;
    }
    const uint8_t away =
        v == 0.0f ? target != 0.0f : (target * v > 0.0f && fabsf(target) > fabsf(v));
    const float tau = a->tau * (away ? SPEED_UP_MASS : MIN_MASS);
    const float step = PERIOD_S / tau < 1.0f ? PERIOD_S / tau : 1.0f;
    const float next = v + (target - v) * step;
    v = (v != 0.0f && next * v < 0.0f) ? 0.0f : next;
    g_model_v[k] = v;
    if (!g_drives_on) {
        g_stall_mm[k] = 0.0f;
        return 1;
    }
    if (over > 0.0f) g_stall_mm[k] += fabsf(v) * PERIOD_S;
    if (g_stall_mm[k] < STALL_MM) return 1;
    raise_fault(FAULT_ENCODER);
    return 0;
}

/* DcAxisLoop::update, the engineered law. */
static float axis_loop(uint8_t k, uint8_t phase, float sp, float vel, float acc) {
    const AxisParams* a = &kAxis[k];
    const float e = sp - g_measured[k];
    if (phase == IN_POSITION) {
        g_integral[k] = 0.0f;
        return 0.0f;
    }
    const uint8_t settling = phase == AXIS_SETTLING;
    const float toward = settling ? e : vel;
    const float coulomb = a->coulomb + (settling ? 100.0f / DUTY_MAX : 0.0f);
    const float friction = toward > 0.0f ? coulomb : toward < 0.0f ? -coulomb : 0.0f;
    const float ff = a->kff * (vel + a->tau * acc) + friction;
    const float free = ff + a->kp * e + a->ki * g_integral[k];
    const uint8_t into = (free > CLAMP_PERCENT && e > 0.0f) || (free < -CLAMP_PERCENT && e < 0.0f);
    if (!into) g_integral[k] += e * PERIOD_S * (settling ? SETTLE_BOOST : 1.0f);
    float u = ff + a->kp * e + a->ki * g_integral[k];
    if (u > CLAMP_PERCENT) u = CLAMP_PERCENT;
    if (u < -CLAMP_PERCENT) u = -CLAMP_PERCENT;
    return u;
}

static void begin_move(float x, float y) {
    if (!g_drives_on || g_fault != FAULT_NONE) return;
    plan_line(g_commanded[0], g_commanded[1], x, y);
    g_plan_ticks = 0;
    g_settle_ticks = 0;
    g_settling_for = 0;
    g_phase = MOVING;
}

/* One period of DcTableMotion::tick. */
static void motion_tick(void) {
    int16_t counted[2];
    read_encoders(counted);
    for (uint8_t k = 0; k < 2; ++k) {
        poll_rx();
        if (!check_encoder(k, counted[k])) break;
    }
    poll_rx();
    for (uint8_t k = 0; k < 2; ++k)
        if (g_drives_on && g_over_current[k]) raise_fault(FAULT_OVER_CURRENT);
    if (!g_drives_on) return;
    if (g_phase == MOVING) {
        ++g_plan_ticks;
        const float t = (float)g_plan_ticks * PERIOD_S;
        float s, v, a;
        plan_at(t, &s, &v, &a);
        for (uint8_t k = 0; k < 2; ++k) {
            g_commanded[k] = g_plan.start[k] + g_plan.dir[k] * s;
            g_cmd_v[k] = g_plan.dir[k] * v;
            g_cmd_a[k] = g_plan.dir[k] * a;
        }
        if (t >= g_plan.duration) {
            for (uint8_t k = 0; k < 2; ++k)
                g_cmd_v[k] = g_cmd_a[k] = 0.0f;
            g_phase = SETTLING;
            g_settle_ticks = 0;
            g_settling_for = 0;
        }
    }
    poll_rx();
    float u[2];
    float worst = 0.0f;
    uint8_t in_window = 1;
    const uint8_t still = g_phase != MOVING;
    for (uint8_t k = 0; k < 2; ++k) {
        const float e = g_commanded[k] - g_measured[k];
        if (fabsf(e) > worst) worst = fabsf(e);
        /* Never narrower than half a count (+1e-9 mm in the emulator: below float's grain). */
        float window = 0.5f * kAxis[k].mmPerCount;
        if (window < WINDOW_MM) window = WINDOW_MM;
        const uint8_t axis_in = fabsf(e) <= window;
        in_window = in_window && axis_in;
        const uint8_t phase = !still ? TRACKING : axis_in ? IN_POSITION : AXIS_SETTLING;
        poll_rx();
        u[k] = axis_loop(k, phase, g_commanded[k], g_cmd_v[k], g_cmd_a[k]);
    }
    poll_rx();
    if (worst > FOLLOWING_MM) {
        raise_fault(FAULT_FOLLOWING);
        return;
    }
    for (uint8_t k = 0; k < 2; ++k) {
        g_drive[k] = u[k];
        write_drive(k, u[k]);
    }
    if (g_phase == SETTLING) {
        ++g_settling_for;
        g_settle_ticks = in_window ? (uint8_t)(g_settle_ticks + 1) : 0;
        if (g_settle_ticks >= IN_POSITION_TICKS)
            g_phase = IDLE;
        else if ((float)g_settling_for * PERIOD_S > SETTLE_TIMEOUT_S)
            raise_fault(FAULT_SETTLE);
    }
}

/* ---- the board's program: TableFirmware ---- */
static uint16_t g_running[2], g_running_from[2]; /* the set point running, the one before */

static void answer(uint8_t code, uint16_t x, uint16_t y, uint16_t bx, uint16_t by) {
    const uint8_t a[ANSWER_BYTES - 1] = {code,
                                         (uint8_t)(x >> 8), (uint8_t)x,
                                         (uint8_t)(y >> 8), (uint8_t)y,
                                         (uint8_t)(bx >> 8), (uint8_t)bx,
                                         (uint8_t)(by >> 8), (uint8_t)by,
                                         moves};
    /* An answer takes 11.5 ms on the line; a host that sends set points faster (a flood: a NAK
       every 4.2 ms) fills the 63 bytes: the answer that does not fit whole is not sent at all,
       and counted, so what goes out is always whole frames (a partial one would cost the
       host's decoder the next frame too). */
    cli();
    const uint8_t room = tx_room();
    sei();
    if (room < ANSWER_BYTES) {
        ++stat_answers_dropped;
        return;
    }
    uint8_t sum = 0;
    for (uint8_t i = 0; i < sizeof a; ++i) {
        send_byte(a[i]);
        sum = (uint8_t)(sum + a[i]);
    }
    send_byte(sum);
}

static void handle(uint16_t x, uint16_t y) {
    ++stat_set_points;
    /* The board answers the move running; a set point that completes meanwhile is the
       host's repeat of it (one in flight): dropped, the bytes kept aligned. */
    if (moving) {
        ++stat_ignored;
        return;
    }
    /* The wire's millimetres are unsigned and the work area starts at 0: only the top. */
    if (x > SOFT_MAX_MM || y > SOFT_MAX_MM) {
        ++stat_refused;
        answer(NAK, x, y, run_x, run_y); /* nothing moves */
        return;
    }
    /* A set point other than the one last begun is a new move; the same again is not. */
    if (x != run_x || y != run_y) ++moves;
    g_running[0] = x, g_running[1] = y;
    g_running_from[0] = run_x, g_running_from[1] = run_y;
    run_x = x, run_y = y;
    moving = 1;
    ++stat_started;
    begin_move((float)x, (float)y);
}

/* TableFirmware::loopTick: the motion's period, then CAN or ACK when the move ended. */
static void loop_tick(void) {
    motion_tick();
    if (g_fault != FAULT_NONE) {
        const uint8_t why = g_fault;
        clear_fault();
        if (moving) {
            moving = 0;
            stat_last_fault = why;
            ++stat_cut;
            answer(CAN, g_running[0], g_running[1], g_running_from[0], g_running_from[1]);
        }
        return;
    }
    if (moving && g_phase == IDLE) {
        moving = 0;
        ++stat_reached;
        answer(ACK, g_running[0], g_running[1], g_running_from[0], g_running_from[1]);
    }
}

/* The set point's bytes as they come: a gap inside a coordinate's pair is a lost byte. */
static uint8_t g_rx[4], g_have;
static uint32_t g_last_byte_us;

static void receive(uint8_t b, uint32_t now) {
    if ((g_have & 1) && now - g_last_byte_us > GAP_US) {
        ++stat_stale;
        g_have = 0;
    }
    g_last_byte_us = now;
    g_rx[g_have++] = b;
    if (g_have < 4) return;
    g_have = 0;
    handle((uint16_t)(g_rx[0] << 8 | g_rx[1]), (uint16_t)(g_rx[2] << 8 | g_rx[3]));
}

#ifdef TABLE_CALIBRATION
/* ---- the calibration image (table-calibration.elf): the emulator's open-loop program
   (TableFirmware::Mode::Calibration, docs/protocols.md B "The calibration program"): one axis
   forward at a fixed PWM, its count (every edge) sent LSB then MSB every 32 ms while under
   1300; at the first check at or above 1300 the PWM stops and the board falls silent. The seed's
   own program (firmware/seed004/calibration.c) ramps its PWM until the first pulse, waits 10 ms
   between the two bytes and runs at 38400 bit/s; this one follows the emulator (xy.md). ---- */
#ifndef CAL_AXIS
#define CAL_AXIS 0 /* x: the seed drives OC1A and counts INT4; -DCAL_AXIS=1 for y */
#endif
#ifndef CAL_PERCENT
#define CAL_PERCENT 25.0f /* TableFirmware::kCalibrationPercent */
#endif
#define CAL_PERIOD_MS 32 /* table_wire::kCalibrationPeriodS */
#define CAL_STOP 1300    /* seed 004: while (pulsos < 1300) */

volatile uint16_t cal_pulses;      /* the count (pulsos) at the last check */
volatile uint8_t cal_done;         /* the PWM stopped at 1300 */
volatile uint32_t stat_counts_sent; /* counts sent, 2 bytes each */

static void calibration_run(void) {
    uint32_t next = CAL_PERIOD_MS;
    write_drive(CAL_AXIS, CAL_PERCENT);
    for (;;) {
        cli();
        const uint32_t ms = g_ms;
        sei();
        if (ms < next) {
            cli();
            if (g_ms < next) {
                sleep_enable();
                sei();
                sleep_cpu();
                sleep_disable();
            }
            sei();
            continue;
        }
        next += CAL_PERIOD_MS;
        cli();
        cal_pulses = g_edges[CAL_AXIS];
        sei();
        if (cal_done) continue;
        if (cal_pulses < CAL_STOP) {
            send_byte((uint8_t)(cal_pulses & 0xFF)); /* LSB first */
            send_byte((uint8_t)(cal_pulses >> 8));
            ++stat_counts_sent;
            continue;
        }
        cal_done = 1;
        write_drive(CAL_AXIS, 0.0f);
    }
}
#endif

int main(void) {
    cli();
    DDRB = 0xFF; /* PB5, PB6: PWM; the rest unused, driven low */
    PORTB = 0;
    DDRC = 0xFF; /* PC0, PC1: direction bits */
    PORTC = 0;
    DDRE = (1 << PE1); /* TXD0 out; RXD0, the encoders and the over-current inputs in */
    PORTE = 0;
    pwm_start();
    /* INT4..INT7 on rising edges (the seed's EICRB = 0xFF), enabled. */
    EICRB = 0xFF;
    EIFR = 0xF0;
    EIMSK |= 0xF0;
    /* UART0: 9600 bit/s at 8 MHz with U2X (UBRR0 = 103, as the seed), 8N1. */
    UBRR0H = 0;
    UBRR0L = 103;
    UCSR0A = (1 << U2X0);
    UCSR0C = (1 << UCSZ01) | (1 << UCSZ00);
    UCSR0B = (1 << RXEN0) | (1 << TXEN0);
    /* Timer 3: CTC on OCR3A, clock / 8 = 1 MHz, 1000 counts: 1 ms. */
    TCCR3A = 0;
    TCCR3B = (1 << WGM32) | (1 << CS31);
    OCR3A = 999;
    ETIMSK |= (1 << OCIE3A);
    set_sleep_mode(SLEEP_MODE_IDLE); /* the timers, the UART and INT4..7 run on */
    {
        int16_t counted[2];
        read_encoders(counted); /* the power-on origin: counts 0, the table where it stands */
        g_commanded[0] = g_measured[0];
        g_commanded[1] = g_measured[1];
    }
    sei();
#ifdef TABLE_CALIBRATION
    (void)loop_tick; /* the main program's, not this image's (the linker drops them) */
    (void)receive;
    calibration_run(); /* never returns; the UART is never read */
#else
    for (;;) {
        poll_rx();
        while (g_ring_tail != g_ring_head) {
            const uint8_t b = g_ring[g_ring_tail];
            const uint32_t at = g_ring_us[g_ring_tail];
            g_ring_tail = (uint8_t)((g_ring_tail + 1) % RX_RING);
            receive(b, at);
        }
        if (!g_loop_due) {
            /* Nothing due: idle until the next interrupt, Timer 3's 1 ms at the latest, so the
               receiver is polled at least every millisecond (it holds 3.1 ms). Checked with
               interrupts off, so a period that falls due meanwhile is not slept through. */
            cli();
            if (!g_loop_due) {
                sleep_enable();
                sei();
                sleep_cpu();
                sleep_disable();
            }
            sei();
            continue;
        }
        {
            cli();
            --g_loop_due;
            sei();
            const uint32_t start = now_us();
            loop_tick();
            const uint32_t took = now_us() - start;
            if (took > stat_loop_us_max) stat_loop_us_max = took > 65535UL ? 65535U : (uint16_t)took;
        }
    }
#endif
}
