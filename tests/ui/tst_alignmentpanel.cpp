// SPDX-License-Identifier: GPL-3.0-or-later
// "Aligned on the sun" in the operator window, offscreen, on the simulator's
// manual clock: the offsets are computed from where the rotator reads and
// where the sun is, the session reads the sun's position at once, the
// offsets are remembered for the link and come back when the window
// connects to it again through the connection bar, and Clear removes them.

#include "../common/simulatorpump.h"
#include "stationwindow.h"
#include "model/savedcalibration.h"
#include "rotor/alignmentpanel.h"
#include "rotor/connectionbar.h"
#include "session/rotatorsession.h"
#include "sky/utctime.h"
#include "tracking/skyalignment.h"
#include "windowfixture.h"

#include <QLabel>
#include <QPushButton>
#include <QTest>

using namespace slew;

namespace {

const sky::Site kStation{55.7, 12.6, 10, {}, {}};
const char kUri[] = "sim:?clock=manual&start_az=150&start_el=40";

} // namespace

class AlignmentPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }
    void init() { m_fixture.reset(new WindowFixture(QString::fromLatin1(kUri))); }
    void cleanup() { m_fixture.reset(); }

    void alignsOnTheSunAndRemembersIt()
    {
        ui::StationWindow &w = *m_fixture->window;
        session::RotatorSession &s = m_fixture->session;
        ui::AlignmentPanel *panel = w.alignmentPanel();
        const double jd = *sky::julianFromIso(QStringLiteral("2026-06-21T10:00:00Z"));
        panel->setClock([jd] { return jd; });
        panel->setStation(kStation);
        QVERIFY(m_fixture->connectAndWait());
        QVERIFY(std::abs(s.azimuth() - 150) < 0.1);

        panel->findChild<QPushButton *>(QStringLiteral("alignOnSun"))->click();
        const sky::BodyPosition sun = sky::sunPosition(kStation, jd);
        const double seenEl = sun.elevationDeg + tracking::refractionDeg(sun.elevationDeg);
        QVERIFY2(std::abs(s.azimuthOffset() - (sun.azimuthDeg - 150)) < 0.01,
                 qPrintable(panel->findChild<QLabel *>(QStringLiteral("alignmentResult"))->text()));
        QVERIFY(std::abs(s.elevationOffset() - (seenEl - 40)) < 0.01);
        // The next reading is the sun's position.
        QVERIFY(runEventLoopUntil([&] { return std::abs(s.azimuth() - sun.azimuthDeg) < 0.05; }, 5000));
        QVERIFY(std::abs(s.elevation() - seenEl) < 0.05);
        QVERIFY(panel->findChild<QLabel *>(QStringLiteral("alignmentOffsets"))->text().contains(
            QString::number(s.azimuthOffset(), 'f', 2)));
        // Remembered for this link, and put back on the next connection to it.
        const auto saved = model::savedCalibration(s.uri());
        QVERIFY(saved && std::abs(saved->azDeg - s.azimuthOffset()) < 1e-3);
        s.disconnectFromRotator();
        model::RotatorProfile bare = s.profile();
        bare.azOffsetDeg = bare.elOffsetDeg = 0;
        s.setProfile(bare);
        QVERIFY(m_fixture->connectAndWait());
        QVERIFY(std::abs(s.azimuthOffset() - saved->azDeg) < 1e-3);

        panel->findChild<QPushButton *>(QStringLiteral("clearOffsets"))->click();
        QCOMPARE(s.azimuthOffset(), 0.0);
        QCOMPARE(s.elevationOffset(), 0.0);
        QVERIFY(runEventLoopUntil([&] { return std::abs(s.azimuth() - 150) < 0.05; }, 5000));
    }

    void refusesAtNightAndChangesNothing()
    {
        ui::StationWindow &w = *m_fixture->window;
        session::RotatorSession &s = m_fixture->session;
        ui::AlignmentPanel *panel = w.alignmentPanel();
        const double night = *sky::julianFromIso(QStringLiteral("2026-12-21T23:00:00Z"));
        panel->setClock([night] { return night; });
        panel->setStation(kStation);
        QVERIFY(m_fixture->connectAndWait());
        panel->findChild<QPushButton *>(QStringLiteral("alignOnSun"))->click();
        QCOMPARE(s.azimuthOffset(), 0.0);
        QVERIFY(panel->findChild<QLabel *>(QStringLiteral("alignmentResult"))->text().contains(QStringLiteral("too low")));
    }

private:
    std::unique_ptr<WindowFixture> m_fixture;
};

QTEST_MAIN(AlignmentPanelTest)
#include "tst_alignmentpanel.moc"
