// SPDX-License-Identifier: GPL-3.0-or-later
#include "windowfixture.h"

#include <QLineEdit>

#include "sim/simulatorscheme.h"
#include "sky/site.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"
#include "tracking/stationclock.h"
#include "transport/link.h"

#include <QCoreApplication>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QStandardPaths>
#include <QTest>

#include <cmath>

void WindowFixture::prepareApplication()
{
    QStandardPaths::setTestModeEnabled(true);
    // Settings of this process only: two test runs at once (a developer's and
    // CI's) must not see each other's remembered connection or preferences.
    static QTemporaryDir settingsDir;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settingsDir.path());
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settingsDir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("SlewTests"));
    QCoreApplication::setApplicationName(QStringLiteral("slew-ui-tests"));
    QSettings().clear();
    slew::sim::registerSimulatorScheme();
}

WindowFixture::WindowFixture(const QString &uri_)
    : session(*station.session()), window(std::make_unique<slew::ui::StationWindow>(&station)), uri(uri_)
{
    QObject::connect(&session, &slew::session::RotatorSession::bytesSent, &session,
                     [this](const QByteArray &bytes) { sent << QString::fromLatin1(bytes).trimmed(); });
    QObject::connect(&session, &slew::session::RotatorSession::positionChanged, &session,
                     [this](double az, double el, bool stale) {
                         if (stale)
                             return;
                         recent.emplace_back(az, el);
                         lastFreshMs = nowMs();
                         if (recent.size() > 6)
                             recent.pop_front();
                     });
    clock.start();
    pump.follow(&session); // moves manual-clock simulators only
    window->show();
}

bool WindowFixture::waitFor(const std::function<bool()> &pred, int timeoutMs)
{
    return runEventLoopUntil(pred, timeoutMs);
}

qint64 WindowFixture::nowMs() const
{
    if (const auto *link = session.link(); link && link->clockIsStepped())
        return qint64(link->clockSeconds().value_or(0.0) * 1000.0);
    return clock.elapsed();
}

bool WindowFixture::holdClockWhen(const std::function<bool()> &pred, int timeoutMs)
{
    bool held = pred();
    if (held)
        pump.pause();
    const QMetaObject::Connection c = QObject::connect(
        &session, &slew::session::RotatorSession::positionChanged, &session, [&](double, double, bool stale) {
            if (!held && !stale && pred()) {
                held = true;
                pump.pause();
            }
        });
    const bool ok = waitFor([&] { return held; }, timeoutMs);
    QObject::disconnect(c);
    return ok;
}

bool WindowFixture::connectAndWait(int timeoutMs)
{
    window->connectTo(uri);
    return waitFor([this] { return session.isConnected() && session.capabilities().probed && recent.size() >= 2; },
                           timeoutMs);
}

bool WindowFixture::loadElementSets(const QString &file)
{
    slew::sky::ElementSetSources *sets = window->elementSets();
    sets->setUrls({QUrl::fromLocalFile(file)});
    QSignalSpy loaded(sets, &slew::sky::ElementSetSources::finished);
    sets->refresh();
    return loaded.count() > 0 || loaded.wait(5000);
}

bool WindowFixture::rehearseAt(const QString &iso, double rate, const QString &locator)
{
    slew::sky::Site place;
    QString error;
    const std::optional<double> start = slew::sky::julianFromIso(iso);
    if (!start || !slew::sky::parseSite(locator, &place, &error))
        return false;
    station.clock()->rehearse(*start, rate);
    station.setPlace(place);
    return true;
}

int WindowFixture::sentCount(const QRegularExpression &line) const
{
    int n = 0;
    for (const QString &s : sent) {
        if (line.match(s).hasMatch())
            ++n;
    }
    return n;
}

bool WindowFixture::isStill(double tolerance) const
{
    if (recent.size() < 6)
        return false;
    for (const QPointF &p : recent) {
        if (std::abs(p.x() - recent.back().x()) > tolerance || std::abs(p.y() - recent.back().y()) > tolerance)
            return false;
    }
    return true;
}

bool WindowFixture::waitUntilStill(int timeoutMs)
{
    // Forget positions from before the call: stillness must be seen afresh.
    recent.clear();
    return waitFor([this] { return isStill(); }, timeoutMs);
}

bool WindowFixture::waitUntilAt(double az, double el, double tolerance, int timeoutMs)
{
    return waitFor(
        [&] {
            return session.hasPosition() && !session.positionStale() && std::abs(session.azimuth() - az) < tolerance
                && std::abs(session.elevation() - el) < tolerance;
        },
        timeoutMs);
}

WindowFixture::AfterStop WindowFixture::watchAfterStop(QPointF pressed, int restWithinMs)
{
    AfterStop r;
    r.pressed = pressed;
    const qint64 stoppedAt = nowMs();
    if (!waitFor([&] { return lastFreshMs >= stoppedAt + restWithinMs; }, restWithinMs + 10000))
        return r;
    r.first = recent.back();
    const qint64 firstAt = lastFreshMs;
    if (!waitFor([&] { return lastFreshMs >= firstAt + 1000; }, 11000))
        return r;
    r.second = recent.back();
    r.valid = true;
    return r;
}

bool WindowFixture::AfterStop::atRest() const
{
    return valid && std::abs(second.x() - first.x()) < 0.05 && std::abs(second.y() - first.y()) < 0.05;
}

double WindowFixture::AfterStop::travel() const
{
    return std::max(std::abs(first.x() - pressed.x()), std::abs(first.y() - pressed.y()));
}

QString WindowFixture::AfterStop::describe() const
{
    auto at = [](QPointF p) { return QStringLiteral("%1/%2").arg(p.x(), 0, 'f', 2).arg(p.y(), 0, 'f', 2); };
    return QStringLiteral("pressed at %1, then %2, a second later %3%4")
        .arg(at(pressed), at(first), at(second), valid ? QString() : QStringLiteral(" (no position came)"));
}

void WindowFixture::typeInto(QLineEdit *field, const QString &text)
{
    field->setFocus();
    field->selectAll();
    QTest::keyClick(field, Qt::Key_Backspace);
    QTest::keyClicks(field, text);
}
