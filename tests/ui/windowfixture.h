// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One operator window on one in-process simulator, for the widget tests:
// finds widgets by objectName, keeps every line the session sent, and
// remembers the latest positions so a test can ask whether the rotator is
// still. Waiting is by predicate (QTest::qWaitFor), never by sleeping.
//
// A `sim:` URI with clock=manual runs on simulated time: the fixture pumps
// the simulator from the event loop, the session keeps its time, and times
// the fixture measures (restWithinMs, lastFreshMs) are simulated
// milliseconds. As simulated time runs far faster than a test looks, a
// passing moment is caught with holdClockWhen().

#include "../common/simulatorpump.h"
#include "stationwindow.h"
#include "session/rotatorsession.h"
#include "station/station.h"

#include <QElapsedTimer>
#include <QPointF>
#include <QRegularExpression>
#include <QStringList>

#include <deque>
#include <functional>
#include <memory>

class QLineEdit;

class WindowFixture {
public:
    // Call once per test executable: test settings, the sim: scheme.
    static void prepareApplication();

    // The fast SatNOGS-class simulator unless a test names another: most
    // window tests are about the window, and a fast rotator keeps them short.
    static constexpr const char *fastSim = "sim:?model=satnogs";
    static constexpr const char *fastSimOnItsClock = "sim:?model=satnogs&clock=manual";
    explicit WindowFixture(const QString &uri = QString::fromLatin1(fastSim));

    // Connects through the connection bar and waits for the probe and a position.
    bool connectAndWait(int timeoutMs = 10000);
    // The station's element sets from a file of the test's, loaded.
    bool loadElementSets(const QString &file);
    // The station at `locator` on a clock started at `iso`, `rate` times real time.
    bool rehearseAt(const QString &iso, double rate, const QString &locator = QStringLiteral("JO65hq"));

    template <typename T>
    T *find(const QString &name) const
    {
        return window->findChild<T *>(name);
    }

    int sentCount(const QRegularExpression &line) const; // lines sent that match
    bool isStill(double toleranceDeg = 0.02) const;     // the last positions agree
    bool waitUntilStill(int timeoutMs = 15000);
    bool waitUntilAt(double az, double el, double toleranceDeg = 0.5, int timeoutMs = 20000);

    // What followed a Stop: the position when it was pressed, the first fresh
    // position reported restWithinMs later, and the first one a second after
    // that. At rest when the last two agree within 0.05°.
    struct AfterStop {
        QPointF pressed, first, second;
        bool valid = false;
        bool atRest() const;
        double travel() const; // the larger axis' distance from pressed to first
        QString describe() const;
    };
    // Call right after pressing Stop, with the position seen before it.
    AfterStop watchAfterStop(QPointF pressed, int restWithinMs);
    QPointF lastPosition() const { return recent.empty() ? QPointF() : recent.back(); }

    // runEventLoopUntil (simulatorpump.h): the loop, and so the pump, runs flat out.
    static bool waitFor(const std::function<bool()> &pred, int timeoutMs);
    // Replaces a field's text as the operator would: select, erase, type.
    static void typeInto(QLineEdit *field, const QString &text);

    // Waits until pred() holds on a fresh position, and holds a manual
    // clock still from that position on, until releaseClock().
    bool holdClockWhen(const std::function<bool()> &pred, int timeoutMs = 15000);
    void releaseClock() { pump.resume(); }
    // The link's stepped clock where it keeps one, else the wall clock.
    qint64 nowMs() const;

    // The window's station, as the application makes it; `session` is its
    // (first) rotor's.
    slew::station::Station station;
    slew::session::RotatorSession &session;
    SimulatorPump pump;
    std::unique_ptr<slew::ui::StationWindow> window;
    QString uri;
    QStringList sent;
    std::deque<QPointF> recent; // az, el of the latest fresh positions
    QElapsedTimer clock;
    qint64 lastFreshMs = -1;    // clock time of recent.back()
};
