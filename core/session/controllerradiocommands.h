// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Easycomm station commands for the radios (the protocol documents'
// tables: `UP` and `DN`, the uplink and downlink frequencies in Hz, `UM`
// and `DM` their modes), on a session's link. A station controller that
// drives the radios itself takes the Doppler-corrected frequencies this
// way (radio/controllerradio.h).
//
// Each goes through the session: a setting is written at once (it has no
// answer), a reading is a request in the queue like any query, so neither
// ever cuts into a poll's answer. Easycomm I takes the settings but answers
// nothing: canRead() says whether readings are possible. A session makes
// its own (RotatorSession::radioCommands()).

#include "sessiontypes.h"

#include "protocol/message.h"

#include <QObject>

namespace slew::session {

class ControllerChannel;

class ControllerRadioCommands : public QObject {
    Q_OBJECT
public:
    enum class Path { Uplink, Downlink };
    Q_ENUM(Path)

    // What the lines carry: DN/UP whole hertz of ten digits at most, DM/UM
    // a mode of one to eight letters or digits.
    static constexpr double kHighestHz = 9999999999.0;
    static constexpr qsizetype kLongestMode = 8;

    // The session owns this (and so outlives it) and speaks for it.
    explicit ControllerRadioCommands(ControllerChannel *channel);

    // The session's dialect has the station commands (UP, DN, UM, DM).
    bool isSupported() const;
    // ...and answers their queries (Easycomm II and later).
    bool canRead() const;

    // `UP145900000` / `DN435000000`: whole hertz, ten digits at most.
    CommandResult setFrequency(Path path, double hz);
    // `UMUSB` / `DMFM`: a mode name of 1 to 8 letters or digits.
    CommandResult setMode(Path path, const QString &mode);
    // `UP` / `DN`: frequencyReported() follows.
    CommandResult readFrequency(Path path);

signals:
    void frequencyReported(slew::session::ControllerRadioCommands::Path path, double hz);
    void modeReported(slew::session::ControllerRadioCommands::Path path, const QString &mode);

public:
    // A UP, DN, UM or DM line the controller sent (the session hands each here).
    void read(const protocol::Message &m);

private:
    CommandResult refuseUnlessSupported();

    ControllerChannel *m_channel;
};

} // namespace slew::session
