// SPDX-License-Identifier: GPL-3.0-or-later
// The wizard opened on a window that is connected sets up that rotator
// through that connection: no probe, no second simulator, no jump to 0/0.
// Probing another link asks first, and only a yes disconnects the window.
#include "../common/simulatorpump.h"

#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulatorscheme.h"
#include "wizard/setupwizard.h"

#include <QAbstractButton>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPointer>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <memory>

using namespace slew;
using session::RotatorSession;
using ui::SetupWizard;

namespace {
// A rotator the window has turned somewhere: a fresh simulator starts at 0/0.
const QString kUri = QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=200&start_el=30");
} // namespace

class WizardConnectionTest : public QObject {
    Q_OBJECT

    std::unique_ptr<RotatorSession> m_session;
    std::unique_ptr<SimulatorPump> m_pump;
    QPointer<sim::Simulator> m_windowSimulator;

    template<typename T>
    static T *find(SetupWizard &w, const char *name)
    {
        T *child = w.currentPage()->findChild<T *>(QLatin1String(name));
        if (!child)
            qWarning() << "no" << name << "on page" << w.currentId();
        return child;
    }
    static bool canGoOn(SetupWizard &w) { return w.button(QWizard::NextButton)->isEnabled(); }
    // Still the window's own simulator, with the rotator where it was.
    bool windowConnectionKept() const
    {
        return m_windowSimulator && sim::simulatorBehind(m_session->link()) == m_windowSimulator
            && m_session->isConnected() && std::fabs(m_session->azimuth() - 200.0) < 0.5
            && std::fabs(m_session->elevation() - 30.0) < 0.5;
    }

private slots:
    void initTestCase() { registerLinkSchemes(); }

    void init()
    {
        QVERIFY(connectPumped(kUri, m_session, m_pump));
        m_windowSimulator = sim::simulatorBehind(m_session->link());
        TRY_VERIFY(windowConnectionKept());
    }
    void cleanup()
    {
        m_pump.reset();
        m_session.reset();
    }

    void aConnectedWindowKeepsItsConnection()
    {
        QSignalSpy states(m_session.get(), &RotatorSession::stateChanged);
        SetupWizard wizard(m_session.get());
        wizard.show();
        // Connect: nothing to probe, the window's link is named.
        QVERIFY(canGoOn(wizard));
        QVERIFY(find<QLabel>(wizard, "windowConnection")->text().contains(m_session->uri()));
        wizard.next();

        // Identify: what the window's connection knows, nothing opened again.
        QCOMPARE(wizard.currentId(), int(SetupWizard::IdentifyPageId));
        TRY_VERIFY(canGoOn(wizard));
        const QString result = find<QLabel>(wizard, "dialectResult")->text();
        QVERIFY2(result.contains(QStringLiteral("easycomm3")) && result.contains(QStringLiteral("window")),
                 qPrintable(result));
        QCOMPARE(wizard.profile().uri, kUri);
        wizard.next();
        QCOMPARE(wizard.currentId(), int(SetupWizard::MechanicsPageId));

        // A while later the window is still on its own simulator, at 200/30.
        const double until = m_windowSimulator->clock().now() + 2.0;
        TRY_VERIFY(m_windowSimulator && m_windowSimulator->clock().now() > until);
        QVERIFY(windowConnectionKept());
        QCOMPARE(states.count(), 0);
    }

    void probingAnotherLinkAsksFirst()
    {
        SetupWizard wizard(m_session.get());
        wizard.show();
        find<QLineEdit>(wizard, "uri")->setText(QStringLiteral("sim:?start_az=5"));
        QVERIFY(!canGoOn(wizard)); // another link: it must answer a probe first
        auto *probe = find<QPushButton>(wizard, "probe");
        auto *question = find<QWidget>(wizard, "disconnectQuestion");
        auto *results = find<QListWidget>(wizard, "baudResults");

        // Asked, and kept: nothing probed, the window untouched.
        QVERIFY(question);
        QTest::mouseClick(probe, Qt::LeftButton);
        QVERIFY(question->isVisible());
        QVERIFY(question->findChild<QLabel *>()->text().contains(m_session->uri()));
        QVERIFY(windowConnectionKept());
        QCOMPARE(results->count(), 0);
        QTest::mouseClick(find<QPushButton>(wizard, "keepConnection"), Qt::LeftButton);
        QVERIFY(!question->isVisible());
        const double until = m_windowSimulator->clock().now() + 1.0;
        TRY_VERIFY(m_windowSimulator && m_windowSimulator->clock().now() > until);
        QVERIFY(windowConnectionKept());
        QCOMPARE(results->count(), 0);
        QVERIFY(!canGoOn(wizard));

        // Asked again, and yes: the window lets go, then the probe runs.
        QSignalSpy stops(m_session.get(), &RotatorSession::stopSent);
        QTest::mouseClick(probe, Qt::LeftButton);
        QTest::mouseClick(find<QPushButton>(wizard, "disconnectAndProbe"), Qt::LeftButton);
        QCOMPARE(stops.count(), 1); // the rotator is stopped before the link goes
        TRY_VERIFY(m_session->state() == RotatorSession::State::Disconnected);
        TRY_VERIFY_WITH_TIMEOUT(canGoOn(wizard), 10000);
        QVERIFY(results->item(0)->text().contains(QStringLiteral("answered")));
    }
};

QTEST_MAIN(WizardConnectionTest)
#include "tst_wizardconnection.moc"
