// The window's keys as the platform delivers them: a held arrow key is one
// press, a run of autorepeats and one release, and only the first and the
// last may reach the wire, as with the on-screen jog button held down.
// Space is Stop: Enter on a go-to and a click on a tab or a group box take
// the focus out of the text field, and in a text field Space is Stop while
// the rotator moves and a space while it is idle.
//
// Keys go to the window's QWindow, as the platform hands them over, which
// passes them to the focus widget. A held key on X11 is a press, then
// release/press pairs sharing one timestamp each, then a release; Qt marks
// the pairs as autorepeat only when it sees both at once, and a busy window
// on a real X server gets most of them unmarked (seen under Xvfb with
// xdotool keydown). Both kinds are sent here.

#include "windowfixture.h"

#include "eventlog.h"

#include <QLineEdit>
#include <QPushButton>
#include <QTabBar>
#include <QTabWidget>
#include <QTest>
#include <QWindow>

namespace {

// A nonzero speed (VL/VR/VU/VD) starts an axis; SA/SE stop it. The zero
// speed the session sends after a stop to hold the drive starts nothing.
const QRegularExpression kStart(QStringLiteral("^V[LRUD]0*[1-9]"));
const QRegularExpression kStop(QStringLiteral("^S[AE]\\b"));

void key(QWidget *window, QEvent::Type type, Qt::Key k, bool autoRepeat, const QString &text = QString(),
         ulong timestamp = 0)
{
    QKeyEvent event(type, k, Qt::NoModifier, text, autoRepeat);
    event.setTimestamp(timestamp);
    QCoreApplication::sendEvent(window->windowHandle(), &event);
}

// Lets the session poll a few more times, so that anything a key started has
// gone out before the lines are counted.
void settle(WindowFixture &f)
{
    const qsizetype before = f.sent.size();
    QVERIFY(f.waitFor([&] { return f.sent.size() >= before + 3; }, 5000));
}


} // namespace

class TestKeyboard : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { WindowFixture::prepareApplication(); }

    void heldArrowIsOneStartOneStop_data()
    {
        QTest::addColumn<Qt::Key>("arrow");
        QTest::addColumn<bool>("marked"); // Qt set isAutoRepeat on the pairs
        for (bool marked : {true, false}) {
            const char *how = marked ? "marked" : "unmarked";
            QTest::addRow("left, %s", how) << Qt::Key_Left << marked;
            QTest::addRow("right, %s", how) << Qt::Key_Right << marked;
            QTest::addRow("up, %s", how) << Qt::Key_Up << marked;
            QTest::addRow("down, %s", how) << Qt::Key_Down << marked;
        }
    }

    void heldArrowIsOneStartOneStop()
    {
        QFETCH(Qt::Key, arrow);
        QFETCH(bool, marked);
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->activateWindow();
        QVERIFY(f.window->isActiveWindow()); // offscreen: at once
        f.find<QWidget>(QStringLiteral("polarPlot"))->setFocus();
        // Start where every direction has room to move.
        QVERIFY(f.session.gotoPosition(180.0, 45.0));
        QVERIFY(f.waitUntilAt(180.0, 45.0));
        QVERIFY(f.waitUntilStill());
        f.sent.clear();

        ulong ms = 1000; // the X server's key timestamps
        key(f.window.get(), QEvent::KeyPress, arrow, false, QString(), ms);
        settle(f);
        QCOMPARE(f.sentCount(kStart), 1);
        ms += 500; // the usual delay before the first repeat
        for (int i = 0; i < 25; ++i, ms += 40) { // a second of the usual 25 Hz repeat
            key(f.window.get(), QEvent::KeyRelease, arrow, marked, QString(), ms);
            key(f.window.get(), QEvent::KeyPress, arrow, marked, QString(), ms);
            settle(f);
        }
        QCOMPARE(f.sentCount(kStop), 0);
        QCOMPARE(f.sentCount(kStart), 1);
        key(f.window.get(), QEvent::KeyRelease, arrow, false, QString(), ms);
        QVERIFY(f.waitFor([&] { return f.sentCount(kStop) >= 1; }, 5000));
        settle(f);
        QCOMPARE(f.sentCount(kStart), 1);
        QCOMPARE(f.sentCount(kStop), 1);
        QVERIFY(f.waitUntilStill());
    }

    void heldJogButtonIsOneStartOneStop_data()
    {
        QTest::addColumn<QString>("button");
        QTest::newRow("left") << "jogLeft";
        QTest::newRow("right") << "jogRight";
        QTest::newRow("up") << "jogUp";
        QTest::newRow("down") << "jogDown";
    }

    void heldJogButtonIsOneStartOneStop()
    {
        QFETCH(QString, button);
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        QVERIFY(f.session.gotoPosition(180.0, 45.0));
        QVERIFY(f.waitUntilAt(180.0, 45.0));
        QVERIFY(f.waitUntilStill());
        f.sent.clear();

        auto *b = f.find<QPushButton>(button);
        QVERIFY(b);
        QTest::mousePress(b, Qt::LeftButton);
        for (int i = 0; i < 25; ++i)
            settle(f); // held as long as the key above
        QCOMPARE(f.sentCount(kStart), 1);
        QCOMPARE(f.sentCount(kStop), 0);
        QTest::mouseRelease(b, Qt::LeftButton);
        settle(f);
        QCOMPARE(f.sentCount(kStart), 1);
        QCOMPARE(f.sentCount(kStop), 1);
    }

    void spaceStopsAfterEnterInGoto()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->activateWindow();
        QVERIFY(f.window->isActiveWindow()); // offscreen: at once
        auto *az = f.find<QLineEdit>(QStringLiteral("gotoAzimuth"));
        auto *el = f.find<QLineEdit>(QStringLiteral("gotoElevation"));
        const double farAz = f.session.azimuth() < 180.0 ? 300.0 : 20.0;
        WindowFixture::typeInto(az, QString::number(farAz));
        WindowFixture::typeInto(el, QStringLiteral("60"));
        key(f.window.get(), QEvent::KeyPress, Qt::Key_Return, false, QStringLiteral("\r"));
        key(f.window.get(), QEvent::KeyRelease, Qt::Key_Return, false, QStringLiteral("\r"));
        QVERIFY(f.session.activeTarget().has_value()); // Enter sent the go-to
        QVERIFY(f.waitFor([&] { return !f.isStill(); }, 5000)); // on its way
        f.sent.clear();

        key(f.window.get(), QEvent::KeyPress, Qt::Key_Space, false, QStringLiteral(" "));
        key(f.window.get(), QEvent::KeyRelease, Qt::Key_Space, false, QStringLiteral(" "));
        settle(f);
        QCOMPARE(f.sentCount(kStop), 1);
        QVERIFY(!az->text().contains(QLatin1Char(' ')));
        QVERIFY(!el->text().contains(QLatin1Char(' ')));
        QVERIFY(f.waitUntilStill());
        QVERIFY(std::abs(f.session.azimuth() - farAz) > 5.0); // stopped on the way, not arrived
    }

    void typingInAFieldNeverStopsAMove()
    {
        // Focus put back in a field by hand while the rotator moves: Space is
        // a space there ("145.95 MHz" typed during a park or a pass), and Esc
        // and Pause still stop from inside it.
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->activateWindow();
        QVERIFY(f.window->isActiveWindow()); // offscreen: at once
        auto *el = f.find<QLineEdit>(QStringLiteral("gotoElevation"));
        const double farAz = f.session.azimuth() < 180.0 ? 300.0 : 20.0;
        QVERIFY(f.session.gotoPosition(farAz, 60.0));
        QVERIFY(f.waitFor([&] { return !f.isStill(); }, 5000));
        el->setFocus();
        el->setText(QStringLiteral("60"));
        el->end(false);
        f.sent.clear();
        key(f.window.get(), QEvent::KeyPress, Qt::Key_Space, false, QStringLiteral(" "));
        key(f.window.get(), QEvent::KeyRelease, Qt::Key_Space, false, QStringLiteral(" "));
        settle(f);
        QCOMPARE(f.sentCount(kStop), 0);
        QCOMPARE(el->text(), QStringLiteral("60 "));
        QVERIFY(!f.isStill());
        for (const Qt::Key stopKey : {Qt::Key_Pause, Qt::Key_Escape}) {
            QVERIFY(f.session.gotoPosition(farAz, 60.0));
            QVERIFY(f.waitFor([&] { return !f.isStill(); }, 5000));
            el->setFocus();
            f.sent.clear();
            key(f.window.get(), QEvent::KeyPress, stopKey, false);
            key(f.window.get(), QEvent::KeyRelease, stopKey, false);
            settle(f);
            QCOMPARE(f.sentCount(kStop), 1);
            QVERIFY(f.waitUntilStill());
        }
        // The event log says which key it was.
        const QString log = f.window->eventLog()->toPlainText();
        QVERIFY2(log.contains(QStringLiteral("Stop (the Pause key)")) && log.contains(QStringLiteral("Stop (the Esc key)")),
                 qPrintable(log));
    }

    void spaceInTypingFieldTypesWhileIdle()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->activateWindow();
        QVERIFY(f.window->isActiveWindow()); // offscreen: at once
        QVERIFY(f.waitUntilStill());
        auto *az = f.find<QLineEdit>(QStringLiteral("gotoAzimuth"));
        az->setFocus();
        az->setText(QStringLiteral("12"));
        az->end(false);
        f.sent.clear();
        key(f.window.get(), QEvent::KeyPress, Qt::Key_Space, false, QStringLiteral(" "));
        key(f.window.get(), QEvent::KeyRelease, Qt::Key_Space, false, QStringLiteral(" "));
        settle(f);
        QCOMPARE(f.sentCount(kStop), 0);
        QCOMPARE(az->text(), QStringLiteral("12 "));
    }

    void clickingATabOrGroupTakesFocusFromAField()
    {
        WindowFixture f(QString::fromLatin1(WindowFixture::fastSimOnItsClock));
        QVERIFY(f.connectAndWait());
        f.window->activateWindow();
        QVERIFY(f.window->isActiveWindow()); // offscreen: at once
        auto *az = f.find<QLineEdit>(QStringLiteral("gotoAzimuth"));
        QTabWidget *tabs = f.window->tabs();
        az->setFocus();
        QCOMPARE(QApplication::focusWidget(), az);
        QTabBar *bar = tabs->tabBar();
        QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(bar->count() - 1).center());
        QVERIFY(QApplication::focusWidget() != az);

        az->setFocus();
        QWidget *group = az->parentWidget();
        while (group && !group->inherits("QGroupBox"))
            group = group->parentWidget();
        QVERIFY(group);
        QTest::mouseClick(group, Qt::LeftButton, {}, QPoint(group->width() / 2, 4));
        QVERIFY(QApplication::focusWidget() != az);
    }
};

QTEST_MAIN(TestKeyboard)
#include "tst_keyboard.moc"
