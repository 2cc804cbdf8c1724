#pragma once
// One operator window on one in-process simulator, for the widget tests:
// finds widgets by objectName, keeps every line the session sent, and
// remembers the latest positions so a test can ask whether the rotator is
// still. Waiting is by predicate (QTest::qWaitFor), never by sleeping.

#include "mainwindow.h"
#include "session/rotatorsession.h"

#include <QPointF>
#include <QRegularExpression>
#include <QStringList>

#include <deque>
#include <memory>

class WindowFixture {
public:
    // Call once per test executable: test settings, the sim: scheme.
    static void prepareApplication();

    explicit WindowFixture(const QString &uri = QStringLiteral("sim:"));

    // Connects through the connection bar and waits for the probe and a position.
    bool connectAndWait(int timeoutMs = 10000);

    template <typename T>
    T *find(const QString &name) const
    {
        return window->findChild<T *>(name);
    }

    int sentCount(const QRegularExpression &line) const; // lines sent that match
    bool isStill(double toleranceDeg = 0.02) const;     // the last positions agree
    bool waitUntilStill(int timeoutMs = 15000);
    bool waitUntilAt(double az, double el, double toleranceDeg = 0.5, int timeoutMs = 20000);

    slew::session::RotatorSession session;
    std::unique_ptr<slew::ui::MainWindow> window;
    QString uri;
    QStringList sent;
    std::deque<QPointF> recent; // az, el of the latest fresh positions
};
