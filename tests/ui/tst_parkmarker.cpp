// SPDX-License-Identifier: GPL-3.0-or-later
// The park marker tells the truth. A fresh profile says park 0/90; the
// simulated controller's park registers (CW7/CW8) hold 0/0, and PARK goes
// where they say. Until the session has read them the plot shows no P and
// Park's text says the park is not read yet; once read (on connect, without
// the Configuration tab ever opened) both show 0/0. A dialect without park
// registers parks at the profile's position, shown from the start.

#include "windowfixture.h"

#include "rotor/polarplotwidget.h"

#include <QLabel>
#include <QPushButton>
#include <QTabWidget>
#include <QTest>

using slew::session::RotatorSession;
using slew::ui::PolarPlotWidget;

class TestParkMarker : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void theMarkerIsTheControllersPark()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock)); // CW7/CW8 hold 0/0
        QCOMPARE(f.session.profile().parkEl, 90.0); // a fresh profile's guess
        auto *plot = f.window->findChild<PolarPlotWidget *>();
        auto *park = f.find<QPushButton>(QStringLiteral("parkButton"));
        auto *said = f.find<QLabel>(QStringLiteral("homeMessage"));
        auto *tabs = f.find<QTabWidget>(QStringLiteral("mainTabs"));
        QVERIFY(plot && park && said && tabs);

        // The moment the link is up, before anything has been read back.
        std::optional<QPointF> markerBefore{QPointF(-1, -1)};
        QString saidBefore;
        connect(&f.session, &RotatorSession::stateChanged, this, [&](RotatorSession::State state) {
            if (state != RotatorSession::State::Connected)
                return;
            markerBefore = plot->park();
            QTest::mouseClick(park, Qt::LeftButton);
            saidBefore = said->text();
        });
        QVERIFY(f.connectAndWait());
        QVERIFY2(!markerBefore, "a park marker before the controller's park was read");
        // Nothing read back: Park says so rather than send PARK blind.
        QVERIFY2(saidBefore.contains(QStringLiteral("no position read from the controller yet")), qPrintable(saidBefore));
        QVERIFY2(!plot->park() || plot->park()->y() < 89.0, "the park marker at the zenith");

        // Read on connect: the plot's P and Park's text are the registers'.
        TRY_VERIFY(plot->park().has_value());
        QCOMPARE(*plot->park(), QPointF(0.0, 0.0));
        QWidget *editor = f.find<QWidget>(QStringLiteral("configEditor")); // read without opening its tab
        QVERIFY(tabs->currentWidget() != editor && !tabs->currentWidget()->isAncestorOf(editor));
        QTest::mouseClick(park, Qt::LeftButton);
        QCOMPARE(said->text(), QStringLiteral("Parking at 0.0°, 0.0°."));
        QVERIFY2(park->toolTip().contains(QStringLiteral("0.0°, 0.0°")), qPrintable(park->toolTip()));
        // And that is where the antenna goes.
        QVERIFY(f.waitUntilAt(0.0, 0.0));
    }

    void withoutParkRegistersTheProfilesParkIsShown()
    {
        WindowFixture f(QStringLiteral("sim:?dialect=gs232b&clock=manual"));
        auto *plot = f.window->findChild<PolarPlotWidget *>();
        auto *said = f.find<QLabel>(QStringLiteral("homeMessage"));
        QVERIFY(plot && said);
        std::optional<QPointF> markerWhenConnected;
        connect(&f.session, &RotatorSession::stateChanged, this, [&](RotatorSession::State state) {
            if (state == RotatorSession::State::Connected)
                markerWhenConnected = plot->park();
        });
        QVERIFY(f.connectAndWait());
        QCOMPARE(markerWhenConnected, std::optional<QPointF>(QPointF(0.0, 90.0)));
        QCOMPARE(plot->park(), std::optional<QPointF>(QPointF(0.0, 90.0)));
        QTest::mouseClick(f.find<QPushButton>(QStringLiteral("parkButton")), Qt::LeftButton);
        QCOMPARE(said->text(), QStringLiteral("Parking at 0.0°, 90.0°."));
        QCOMPARE(f.sentCount(QRegularExpression(QStringLiteral("^CR"))), 0);
    }
};

QTEST_MAIN(TestParkMarker)
#include "tst_parkmarker.moc"
