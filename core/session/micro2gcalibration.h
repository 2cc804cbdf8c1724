// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Micro-2g program's two-point calibration (docs/protocol.md,
// "Micro-2g"), asked for on a session's link. The setup wizard's
// calibration page asks for the A/D readings while the operator turns the
// rotor to its stops, sets each stop and the degree range, and reads back
// what the controller holds.
//
// Each request goes through the session's queue like any query, so it never
// cuts into a poll's answer. Every `Z` line that comes back is handed on by
// calibrationReceived(), every `V` item by adcReadingReceived(); a
// calibration request the controller refuses (`?>`) or leaves unanswered
// ends in calibrationFailed(). A session makes its own (RotatorSession::micro2g()).

#include "sessiontypes.h"

#include "protocol/message.h"
#include "protocol/micro2glistings.h"

#include <QObject>

namespace slew::session {

class ControllerChannel;

class Micro2gCalibration : public QObject {
    Q_OBJECT
public:
    static constexpr int kRotors = 4;
    enum class Point { LeftStop, RightStop, DegreeRange };

    // Reads the session's listing lines from now on; the session owns this
    // (and so outlives it).
    explicit Micro2gCalibration(ControllerChannel *channel);

    // `Z`, done when rotor's line is in.
    CommandResult request(int rotor);
    // `V`: every rotor's A/D reading.
    CommandResult requestAdcReadings();
    // `ZnL mmm` / `ZnR mmm` (the present reading is that stop, at bearing
    // mmm, 0..359) or `ZnD mmm` (90..540 degrees of travel), and `Z` after
    // it on the same request, so what the controller now holds comes back.
    CommandResult set(int rotor, Point point, int value);

signals:
    void calibrationReceived(int rotor, const slew::protocol::Micro2gCalibration &calibration);
    void adcReadingReceived(int rotor, int counts);
    void calibrationFailed(int rotor, const QString &reason);

private:
    // A Z or V listing: handed on; false when it is a command's echo instead.
    bool read(const protocol::Message &m);
    CommandResult queueCalibration(const QByteArray &line, int rotor);
    CommandResult refuseUnlessSupported(protocol::Op op, const QString &what);
    // A link, a dialect with calibration, and a rotor 1..kRotors.
    CommandResult refuseUnlessCalibratable(int rotor, const QString &what);

    ControllerChannel *m_channel;
};

} // namespace slew::session
