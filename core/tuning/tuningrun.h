// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `slew --tune` without a window: connect, wait for the capability probe,
// tune the chosen axes with the tuning sequence, stop the rotator, and say
// what happened as lines of text. The program only parses its options and
// prints these lines (the headless station is built the same way); nothing
// here writes to a terminal.

#include "model/rotatorprofile.h"
#include "session/rotatorsession.h"
#include "tuningsequence.h"

#include <QList>
#include <QObject>

namespace slew::tuning {

class TuningRun : public QObject {
    Q_OBJECT
public:
    struct Options {
        model::RotatorProfile profile; // the link URI is profile.uri
        QList<session::Axis> axes;
        bool apply = false;            // keep the new gains; else the old ones are written back
        double stepDegrees = TuningSettings{}.amplitude;
    };

    explicit TuningRun(const Options &options, QObject *parent = nullptr);

    void start();
    // Ctrl-C: the rotator is stopped and the old gains put back before
    // finished(); before the tuning began, finished() follows at once.
    void interrupt();

    session::RotatorSession &session() { return m_session; }

signals:
    void output(const QString &line);  // progress and the before/after table
    void problem(const QString &line); // why it stopped
    void finished(int exitCode);       // 0 tuned, 1 failed or cancelled

private:
    void begin();
    void end(int exitCode);
    void finishLater(int exitCode);

    Options m_options;
    session::RotatorSession m_session;
    TuningSequence m_sequence;
    bool m_started = false;
    bool m_ended = false;
    QString m_lastLine;
};

} // namespace slew::tuning
