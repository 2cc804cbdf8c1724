#pragma once
// Moves a manual-clock simulator on by a fixed slice every time the event
// loop comes round, so a test runs simulated seconds in wall milliseconds
// while every reply still travels through the event loop as it would on a
// real line. Samples are stamped with the simulator's clock (SampleClock),
// and the session's polling, reply timeouts and stop hold keep the same
// clock (session/linktimer.h), so what happens is the same however fast or
// busy the machine is.
//
// drive() pumps one simulator; follow() pumps whatever manual-clock
// simulator is behind a session's link, through reconnects.

#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"

#include <QEventLoop>
#include <QObject>
#include <QPointer>
#include <QTest>
#include <QTimer>

#include <functional>
#include <memory>

class SimulatorPump : public QObject {
public:
    // Its object name, to find one among a parent's children: the class has
    // no Q_OBJECT (a header-only helper moc never sees), so findChild by its
    // type would take any QObject (and Qt 6.8 refuses to compile it).
    static constexpr char kObjectName[] = "simulatorPump";

    explicit SimulatorPump(double sliceSeconds = 0.005, QObject *parent = nullptr)
        : QObject(parent), m_slice(sliceSeconds)
    {
        setObjectName(QLatin1String(kObjectName));
        m_timer.setInterval(0);
        QObject::connect(&m_timer, &QTimer::timeout, this, [this] {
            slew::sim::Simulator *sim = m_sim;
            if (m_session)
                sim = slew::sim::simulatorBehind(m_session->link());
            if (sim && sim->clock().isManual())
                sim->advance(m_slice);
        });
    }
    void follow(slew::session::RotatorSession *session)
    {
        m_session = session;
        m_timer.start();
    }
    void drive(slew::sim::Simulator *sim)
    {
        m_sim = sim;
        m_timer.start();
    }
    void pause() { m_timer.stop(); }
    void resume() { m_timer.start(); }

private:
    QPointer<slew::sim::Simulator> m_sim;
    QPointer<slew::session::RotatorSession> m_session;
    double m_slice;
    QTimer m_timer;
};

// Runs the event loop until pred() holds or timeoutMs of wall time pass.
// Unlike QTest::qWaitFor, which sleeps 10 ms between passes, it keeps the
// loop (and so a pump) running flat out.
inline bool runEventLoopUntil(const std::function<bool()> &pred, int timeoutMs)
{
    if (pred())
        return true;
    QEventLoop loop;
    QTimer look;
    look.setInterval(0);
    QObject::connect(&look, &QTimer::timeout, &loop, [&] {
        if (pred())
            loop.quit();
    });
    QTimer giveUp;
    giveUp.setSingleShot(true);
    QObject::connect(&giveUp, &QTimer::timeout, &loop, &QEventLoop::quit);
    look.start();
    giveUp.start(timeoutMs);
    loop.exec();
    return pred();
}

// QTRY_*'s counterparts for a pumped clock: QTRY_* sleep 10 ms between
// looks, in which a pumped clock stands still; these keep the loop running.
// Being a nested loop, they do not carry out a deleteLater() made outside
// them: wait for a deletion with QTRY_*, which does.
#define TRY_VERIFY_WITH_TIMEOUT(expr, ms) QVERIFY2(runEventLoopUntil([&] { return bool(expr); }, ms), #expr)
#define TRY_VERIFY2_WITH_TIMEOUT(expr, message, ms)                                                                    \
    do {                                                                                                               \
        runEventLoopUntil([&] { return bool(expr); }, ms);                                                             \
        QVERIFY2(expr, message);                                                                                       \
    } while (false)
#define TRY_VERIFY(expr) TRY_VERIFY_WITH_TIMEOUT(expr, 10000)
#define TRY_COMPARE_WITH_TIMEOUT(actual, expected, ms)                                                                 \
    do {                                                                                                               \
        runEventLoopUntil([&] { return (actual) == (expected); }, ms);                                                 \
        QCOMPARE(actual, expected);                                                                                    \
    } while (false)
#define TRY_COMPARE(actual, expected) TRY_COMPARE_WITH_TIMEOUT(actual, expected, 10000)

// Makes a session on a manual-clock sim: URI, waits for the probe and a
// position, then lets the pump run the simulator's clock.
inline bool connectPumped(const QString &uri, std::unique_ptr<slew::session::RotatorSession> &session,
                          std::unique_ptr<SimulatorPump> &pump)
{
    session = std::make_unique<slew::session::RotatorSession>();
    pump = std::make_unique<SimulatorPump>();
    session->connectTo(uri);
    if (!QTest::qWaitFor([&] { return session->capabilities().probed && session->hasPosition(); }, 5000))
        return false;
    pump->drive(slew::sim::simulatorBehind(session->link()));
    return true;
}
