// SPDX-License-Identifier: GPL-3.0-or-later
#include "tuningrun.h"

#include "session/stopbeforeexit.h"
#include "tuningresult.h"

namespace slew::tuning {

using session::RotatorSession;

TuningRun::TuningRun(const Options &options, QObject *parent)
    : QObject(parent), m_options(options), m_sequence(&m_session)
{
    model::RotatorProfile profile = options.profile;
    profile.pollHz = 50; // a step is measured from the polled positions: poll as often as the session allows
    m_session.setProfile(profile);
    TuningSettings settings;
    settings.amplitude = options.stepDegrees;
    m_sequence.setSettings(settings);

    connect(&m_sequence, &TuningSequence::progress, this, [this](const QString &axisName, int, const QString &what) {
        const QString line = QStringLiteral("%1: %2").arg(axisName, what);
        // Step progress repeats with the time; only phases are said.
        if (!what.contains(u':') && line != m_lastLine)
            emit output(line);
        m_lastLine = line;
    });
    connect(&m_sequence, &TuningSequence::finished, this, [this](const QList<TuningResult> &results) {
        emit output(QString());
        for (const QString &row : formatTuningTable(results).split(u'\n', Qt::SkipEmptyParts))
            emit output(row);
        for (const TuningResult &r : results) {
            const int first = firstGainRegister(r.axis);
            emit output(r.applied ? tr("%1: new gains kept (CW%2..CW%3, read back)")
                                        .arg(axisName(r.axis))
                                        .arg(first)
                                        .arg(first + 2)
                                  : tr("%1: old gains written back; --apply keeps the new ones").arg(axisName(r.axis)));
        }
        end(0);
    });
    connect(&m_sequence, &TuningSequence::failed, this, [this](const QString &reason) {
        emit problem(tr("tuning stopped: %1").arg(reason));
        end(1);
    });
    connect(&m_session, &RotatorSession::capabilitiesChanged, this, [this](const session::Capabilities &caps) {
        if (caps.probed && !m_started)
            begin();
    });
    connect(&m_session, &RotatorSession::stateChanged, this, [this](RotatorSession::State state, const QString &detail) {
        if (state == RotatorSession::State::Disconnected && !m_ended) {
            emit problem(detail);
            m_ended = true;
            finishLater(1);
        }
    });
}

void TuningRun::start()
{
    m_session.connectTo(m_options.profile.uri);
}

void TuningRun::begin()
{
    m_started = true;
    if (!m_sequence.start(m_options.axes, m_options.apply)) {
        emit problem(m_sequence.error());
        end(1);
    }
}

void TuningRun::interrupt()
{
    if (!m_started) {
        end(1);
        return;
    }
    // The sequence stops the rotator and writes the old gains back, then
    // reports failed(), which ends the run.
    m_session.stop(tr("the tuning run was cancelled"));
    m_sequence.cancel();
}

void TuningRun::end(int exitCode)
{
    if (m_ended)
        return;
    m_ended = true;
    // The rotator is left standing: the stop (and its hold) leave the link
    // before finished() lets the program go.
    if (!session::stopThenCall(m_session, tr("the tuning run ended"), this, [this, exitCode] { emit finished(exitCode); }))
        finishLater(exitCode);
}

void TuningRun::finishLater(int exitCode)
{
    // From the event loop, never from inside start(): the program's loop
    // may not be running yet (a bad URI fails while connecting).
    QMetaObject::invokeMethod(this, [this, exitCode] { emit finished(exitCode); }, Qt::QueuedConnection);
}

} // namespace slew::tuning
