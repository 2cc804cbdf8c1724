#include "windowfixture.h"

#include "sim/simulatorscheme.h"

#include <QCoreApplication>
#include <QSettings>
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

WindowFixture::WindowFixture(const QString &uri_) : window(std::make_unique<slew::ui::MainWindow>(&session)), uri(uri_)
{
    QObject::connect(&session, &slew::session::RotatorSession::bytesSent, &session,
                     [this](const QByteArray &bytes) { sent << QString::fromLatin1(bytes).trimmed(); });
    QObject::connect(&session, &slew::session::RotatorSession::positionChanged, &session,
                     [this](double az, double el, bool stale) {
                         if (stale)
                             return;
                         recent.emplace_back(az, el);
                         if (recent.size() > 6)
                             recent.pop_front();
                     });
    window->show();
}

bool WindowFixture::connectAndWait(int timeoutMs)
{
    window->connectTo(uri);
    return QTest::qWaitFor([this] { return session.isConnected() && session.capabilities().probed && recent.size() >= 2; },
                           timeoutMs);
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
    return QTest::qWaitFor([this] { return isStill(); }, timeoutMs);
}

bool WindowFixture::waitUntilAt(double az, double el, double tolerance, int timeoutMs)
{
    return QTest::qWaitFor(
        [&] {
            return session.hasPosition() && !session.positionStale() && std::abs(session.azimuth() - az) < tolerance
                && std::abs(session.elevation() - el) < tolerance;
        },
        timeoutMs);
}
