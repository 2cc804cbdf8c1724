// SPDX-License-Identifier: GPL-3.0-or-later
// The wizard moves the rotator while it covers the window's STOP, so it has
// its own: below every page, next to the one Cancel. Pressed (or Esc) while
// the wizard homes the rotator, the stop reaches the wire, the homing ends
// and the rotator stands still; Esc leaves the wizard open.
#include "../common/simulatorpump.h"

#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulatorscheme.h"
#include "wizard/setupwizard.h"

#include <QAbstractButton>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <memory>

using namespace slew;
using session::RotatorSession;
using ui::SetupWizard;

namespace {

// A homing from here runs for several simulated seconds before it is home.
const QString kUri = QStringLiteral("sim:?clock=manual&unsolicited=1&start_az=40&start_el=20");

const QList<int> kPages{SetupWizard::ConnectPageId, SetupWizard::IdentifyPageId, SetupWizard::MechanicsPageId,
                        SetupWizard::HomingPageId,  SetupWizard::TuningPageId,   SetupWizard::ParkPageId,
                        SetupWizard::SummaryPageId, SetupWizard::CalibrationPageId};

QString withoutMnemonic(QString text)
{
    return text.remove(u'&');
}

} // namespace

class WizardStopTest : public QObject {
    Q_OBJECT

    std::unique_ptr<RotatorSession> m_session;
    std::unique_ptr<SimulatorPump> m_pump;
    QList<QByteArray> m_sent;

    sim::Simulator *simulator() { return sim::simulatorBehind(m_session->link()); }
    bool sentStop() const
    {
        return std::any_of(m_sent.begin(), m_sent.end(), [](const QByteArray &b) { return b.contains("SA SE"); });
    }
    bool axesStopped()
    {
        return simulator()->rotator().axis(sim::Axis::Azimuth).isStopped()
            && simulator()->rotator().axis(sim::Axis::Elevation).isStopped();
    }
    // Once the worm gears have caught the motors, two simulated seconds
    // pass and neither axis moves on.
    void standsStill()
    {
        sim::Simulator *sim = simulator();
        TRY_VERIFY(sim->rotator().axis(sim::Axis::Azimuth).velocity() == 0.0
                   && sim->rotator().axis(sim::Axis::Elevation).velocity() == 0.0);
        const double az = sim->rotator().axis(sim::Axis::Azimuth).position();
        const double el = sim->rotator().axis(sim::Axis::Elevation).position();
        const double until = sim->clock().now() + 2.0;
        TRY_VERIFY(sim->clock().now() > until);
        QCOMPARE(sim->rotator().axis(sim::Axis::Azimuth).position(), az);
        QCOMPARE(sim->rotator().axis(sim::Axis::Elevation).position(), el);
        TRY_VERIFY(std::fabs(m_session->azimuth() - az) < 0.05); // and the window reads it there
    }
    // The wizard at its homing page with homing under way.
    void startHoming(SetupWizard &wizard)
    {
        wizard.setStartId(SetupWizard::HomingPageId);
        wizard.show();
        QCOMPARE(wizard.currentId(), int(SetupWizard::HomingPageId));
        QTest::mouseClick(wizard.currentPage()->findChild<QPushButton *>(QStringLiteral("home")), Qt::LeftButton);
        TRY_VERIFY(m_session->azimuth() < 38.0);
        m_sent.clear();
    }

private slots:
    void initTestCase() { registerLinkSchemes(); }

    void init()
    {
        QVERIFY(connectPumped(kUri, m_session, m_pump));
        m_sent.clear();
        connect(m_session.get(), &RotatorSession::bytesSent, this, [this](const QByteArray &b) { m_sent << b; });
    }
    void cleanup()
    {
        m_pump.reset();
        m_session.reset();
    }

    void everyPageHasTheStop()
    {
        for (int id : kPages) {
            SetupWizard wizard(m_session.get());
            wizard.setStartId(id);
            wizard.show();
            QCOMPARE(wizard.currentId(), id);
            auto *stop = wizard.findChild<QPushButton *>(QStringLiteral("wizardStop"));
            QVERIFY2(stop && stop->isVisible() && stop->isEnabled(), qPrintable(wizard.currentPage()->title()));
        }
    }

    void everyPageHasOneCancel()
    {
        for (int id : kPages) {
            SetupWizard wizard(m_session.get());
            wizard.setStartId(id);
            wizard.show();
            QCOMPARE(wizard.currentId(), id);
            QStringList cancels;
            for (QAbstractButton *b : wizard.findChildren<QAbstractButton *>()) {
                if (b->isVisible() && withoutMnemonic(b->text()).contains(QStringLiteral("cancel"), Qt::CaseInsensitive))
                    cancels << b->text();
            }
            QVERIFY2(cancels.size() == 1, qPrintable(QStringLiteral("%1: %2").arg(wizard.currentPage()->title(),
                                                                                   cancels.join(u','))));
        }
    }

    void theStopEndsHomingAndStopsTheRotator()
    {
        SetupWizard wizard(m_session.get());
        startHoming(wizard);
        if (QTest::currentTestFailed())
            return;
        QSignalSpy stops(m_session.get(), &RotatorSession::stopSent);
        auto *stop = wizard.findChild<QPushButton *>(QStringLiteral("wizardStop"));
        QVERIFY(stop);
        QTest::mouseClick(stop, Qt::LeftButton);
        QVERIFY(stops.count() >= 1);
        QVERIFY(sentStop());
        TRY_VERIFY(axesStopped());
        standsStill();
        QVERIFY(m_session->azimuth() > 5.0); // stopped on the way, not home
        auto *result = wizard.currentPage()->findChild<QLabel *>(QStringLiteral("homingResult"));
        QVERIFY2(result->text().contains(QStringLiteral("cancelled")), qPrintable(result->text()));
        QVERIFY(wizard.currentPage()->findChild<QPushButton *>(QStringLiteral("home"))->isEnabled());
    }

    void theStopEndsAJog()
    {
        SetupWizard wizard(m_session.get());
        wizard.setStartId(SetupWizard::MechanicsPageId);
        wizard.show();
        QTest::mouseClick(wizard.currentPage()->findChild<QPushButton *>(QStringLiteral("jogElevation")),
                          Qt::LeftButton);
        TRY_VERIFY(m_session->elevation() > 20.3);
        m_sent.clear();
        QTest::mouseClick(wizard.findChild<QPushButton *>(QStringLiteral("wizardStop")), Qt::LeftButton);
        QVERIFY(sentStop());
        TRY_VERIFY(axesStopped());
        standsStill();
        QVERIFY(m_session->elevation() < 24.0); // well short of the jog's 25°
        auto *note = wizard.currentPage()->findChild<QLabel *>(QStringLiteral("elDirection"));
        QVERIFY2(note->text().contains(QStringLiteral("Stopped")), qPrintable(note->text()));
    }

    void theStopEndsASpeedMeasurement()
    {
        SetupWizard wizard(m_session.get());
        wizard.setStartId(SetupWizard::TuningPageId);
        wizard.show();
        auto *measure = wizard.currentPage()->findChild<QPushButton *>(QStringLiteral("measureSpeed"));
        QTest::mouseClick(measure, Qt::LeftButton);
        TRY_VERIFY(std::fabs(m_session->azimuth() - 40.0) > 1.0);
        m_sent.clear();
        QTest::mouseClick(wizard.findChild<QPushButton *>(QStringLiteral("wizardStop")), Qt::LeftButton);
        QVERIFY(sentStop());
        TRY_VERIFY(axesStopped());
        standsStill();
        // The page is usable again, and says what happened.
        QVERIFY(measure->isEnabled());
        QVERIFY(wizard.button(QWizard::NextButton)->isEnabled());
        auto *status = wizard.currentPage()->findChild<QLabel *>(QStringLiteral("tuningStatus"));
        QVERIFY2(status->text().contains(QStringLiteral("stopped")), qPrintable(status->text()));
    }

    void escapeStopsAndKeepsTheWizardOpen()
    {
        SetupWizard wizard(m_session.get());
        startHoming(wizard);
        if (QTest::currentTestFailed())
            return;
        QTest::keyClick(wizard.currentPage(), Qt::Key_Escape); // from the page, as a key the page does not use
        QVERIFY(sentStop());
        TRY_VERIFY(axesStopped());
        standsStill();
        QVERIFY(wizard.isVisible());
        QCOMPARE(wizard.currentId(), int(SetupWizard::HomingPageId));
    }
};

QTEST_MAIN(WizardStopTest)
#include "tst_wizardstop.moc"
