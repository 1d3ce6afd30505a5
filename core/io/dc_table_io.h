#pragma once
// The DC XY table's I/O as seed 004's ATmega128 board offers it (xy.md B), per axis (0 x,
// 1 y): Timer1's PWM channel (OCR1A x, OCR1B y, duty 0..ICR1 = 247 at 32 kHz) with a direction
// bit on PORTC (bit 0 x, bit 1 y), the encoder count kept by INT4/INT6, and the over-current
// inputs INT5/INT7, whose interrupt stops Timer1: both PWM channels, since they share it.
#include <cstdint>

namespace trilho {

class DcTableIo {
  public:
    virtual ~DcTableIo() = default;
    /// Duty 0..pwmDutyMax (OCR1x) and the direction bit: false = forward (the count rises),
    /// true = reverse (seed 004, bits_de_giro: "AVANCE: BIT = 0 y RETROCESO: BIT = 1").
    virtual void writePwm(int axis, std::uint16_t duty, bool reverse) = 0;
    /// The 16-bit encoder count; it wraps.
    virtual std::uint16_t readEncoder(int axis) = 0;
    /// The over-current input of the axis' motor; once it fired the PWM stays off (Timer1
    /// stopped) until restartPwm().
    virtual bool readOverCurrent(int axis) = 0;
    /// Reconfigures Timer1 (the firmware's config_pwm) after an over-current: the PWM runs again.
    virtual void restartPwm() = 0;
};

}  // namespace trilho
