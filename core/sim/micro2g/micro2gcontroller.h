// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Micro-2g rotor controller program, simulated: four azimuth rotors on
// one serial line (9600 8N1), each with a potentiometer read through a
// 12-bit A/D converter and turned into a bearing by a two-point calibration,
// driven left or right by relays until the reading is within a tolerance of
// the target. Its command set and the reply formats Slew chose for it are
// in docs/protocol.md ("Micro-2g").
//
// Pure and steppable: handle() takes one command line and returns the
// reply lines, advance() moves the rotors by a time step. No I/O, no clock.

#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <array>
#include <optional>

namespace slew::sim {

struct Micro2gCalibration {
    int leftAdc = 3990;        // A/D reading at the left (counter-clockwise) stop
    double leftBearing = 0;    // the bearing the antenna points to there
    int rightAdc = 2440;       // A/D reading at the right stop
    double rightBearing = 90;  // as entered; the range below is what counts
    double degreeRange = 450;  // degrees of travel from the left stop to the right
};

class Micro2gController {
public:
    static constexpr int kRotors = 4;
    enum class Drive { Off, Left, Right };

    // The rotors as built: where each one's mechanical left stop points
    // (0 for a north-stop installation, 180 for a south-stop one), how fast
    // the relays turn it, and its potentiometer's two ends.
    struct Mechanics {
        double leftStopBearing = 0;
        double degreesPerSecond = 6.0; // a G-2800 class rotator
        double travelDegrees = 450;
        int adcAtLeftStop = 3990;
        int adcAtRightStop = 2440;
    };

    Micro2gController();
    explicit Micro2gController(const std::array<Mechanics, kRotors> &mechanics);

    // One command line, without its terminator; the reply lines, if any.
    QStringList handle(const QString &line);
    // Moves every driven rotor by this much time.
    void advance(double seconds);

    int defaultRotor() const { return m_defaultRotor; }
    // Rotor n is 1..4, as on the wire.
    double heading(int rotor) const;       // what the controller reads: calibration applied
    double trueBearing(int rotor) const;   // where the antenna really points
    double travel(int rotor) const;        // degrees from the mechanical left stop
    int adc(int rotor) const;
    Drive drive(int rotor) const;
    int tolerance(int rotor) const;
    const Micro2gCalibration &calibration(int rotor) const;

    // The switch on the rotator's own control box, which turns the motor
    // without the program: held Left or Right, the rotor turns until it is
    // released (Off) or meets its mechanical stop. While it is held the
    // program's own target is dropped, as an operator would expect.
    void setHandDrive(int rotor, Drive drive);
    Drive handDrive(int rotor) const;
    // The rotor as built, for tests of other installations (a south stop,
    // another potentiometer); it keeps its travel.
    void setMechanics(int rotor, const Mechanics &mechanics);

    // Calibration, presets and tolerances: lost at power-off like the real
    // program, unless the simulator keeps them in a file.
    QJsonObject settings() const;
    QString restoreSettings(const QJsonObject &settings); // empty, or what is wrong

private:
    struct Rotor {
        Mechanics mechanics;
        Micro2gCalibration calibration;
        double travel = 0;
        std::optional<int> targetAdc;
        Drive drive = Drive::Off;
        Drive handDrive = Drive::Off; // the control box's switch
        int tolerance = 20;
        std::array<double, 3> presets{45, 90, 180};
        double stalledSeconds = 0;
    };

    Rotor &rotor(int n) { return m_rotors[size_t(n - 1)]; }
    const Rotor &rotor(int n) const { return m_rotors[size_t(n - 1)]; }
    QString turnTo(int n, double bearing);
    QStringList calibrate(const QString &line);

    std::array<Rotor, kRotors> m_rotors;
    int m_defaultRotor = 1;
};

} // namespace slew::sim
