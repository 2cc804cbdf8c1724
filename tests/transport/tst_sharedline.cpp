// SPDX-License-Identifier: GPL-3.0-or-later
// One controller line shared by a session per rotor (transport/sharedline.h):
// how the wire is shared (queries take turns, commands never wait), where
// answers go, opening and losing the one line, and four sessions driving
// the four rotors of the simulated Micro-2g controller over one line.

#include "../common/queuedreaddevice.h"
#include "../common/simulatorpump.h"
#include "linkschemes.h"
#include "session/rotatorsession.h"
#include "sim/simulator.h"
#include "sim/simulatorscheme.h"
#include "transport/linkfactory.h"
#include "transport/sharedline.h"
#include "transport/sharedlinelink.h"

#include <QPointer>
#include <QSignalSpy>
#include <QTest>

using slew::session::RotatorSession;
using slew::transport::Link;
using slew::transport::LinkResult;
using slew::transport::SharedLine;

namespace {

// The far end of a `testline:` link: records what is written to it, and
// lets the test say what arrives.
class RecordingDevice : public QueuedReadDevice {
public:
    QList<QByteArray> written;

protected:
    qint64 writeData(const char *data, qint64 size) override
    {
        written.append(QByteArray(data, size));
        return size;
    }
};

// A link the test opens, fails and loses by hand.
class TestLine : public Link {
public:
    using Link::Link;
    QIODevice *device() override { return &m_device; }
    void open() override { ++opens; }
    void close() override
    {
        ++closes;
        m_device.close();
    }
    bool isOpen() const override { return m_device.isOpen(); }

    void finishOpening()
    {
        m_device.open(QIODevice::ReadWrite | QIODevice::Unbuffered);
        emit opened();
    }
    void loseIt(const QString &why)
    {
        m_device.close();
        emit lost(why);
    }
    RecordingDevice &far() { return m_device; }

    int opens = 0;
    int closes = 0;

private:
    RecordingDevice m_device;
};

QPointer<TestLine> lastTestLine;

std::unique_ptr<Link> rotorLink(SharedLine &line, int rotor)
{
    LinkResult made = line.makeLink(QStringLiteral("testline:one?rotor=%1").arg(rotor));
    return std::move(made.link);
}

} // namespace

class SharedLineTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        slew::registerLinkSchemes();
        slew::transport::registerLinkScheme(QStringLiteral("testline"), [](const QUrl &, const QString &uri) {
            auto link = std::make_unique<TestLine>(uri);
            lastTestLine = link.get();
            return LinkResult{std::move(link), {}};
        });
    }

    void theLineIsTheUriWithoutItsRotor()
    {
        QCOMPARE(SharedLine::lineUri(QStringLiteral("tcp://host:4001?rotor=3")), QStringLiteral("tcp://host:4001"));
        QCOMPARE(SharedLine::lineUri(QStringLiteral("serial:/dev/ttyUSB0?baud=9600&rotor=2")),
                 QStringLiteral("serial:/dev/ttyUSB0?baud=9600"));
        QCOMPARE(SharedLine::lineUri(QStringLiteral("sim:?rotor=2&dialect=micro2g")), QStringLiteral("sim:?dialect=micro2g"));
        QCOMPARE(SharedLine::lineUri(QStringLiteral("tcp://host:4001")), QStringLiteral("tcp://host:4001"));

        SharedLine line(QStringLiteral("testline:one"));
        QVERIFY(line.isValid());
        const LinkResult elsewhere = line.makeLink(QStringLiteral("testline:two?rotor=1"));
        QVERIFY(!elsewhere.link);
        QVERIFY2(elsewhere.error.contains(QStringLiteral("testline:two")), qPrintable(elsewhere.error));
        QVERIFY(!line.makeLink(QStringLiteral("testline:one?rotor=5")).link);
        const std::unique_ptr<Link> two = rotorLink(line, 2);
        QVERIFY(two);
        QCOMPARE(two->hints().rotor, std::optional<int>(2));
        // Unnamed, it is rotor 1: another rotor's go-to moves the controller's default.
        const LinkResult unnamed = line.makeLink(QStringLiteral("testline:one"));
        QVERIFY(unnamed.link);
        QCOMPARE(unnamed.link->hints().rotor, std::optional<int>(1));

        SharedLine broken(QStringLiteral("nosuchscheme:x"));
        QVERIFY(!broken.isValid());
        const LinkResult none = broken.makeLink(QStringLiteral("nosuchscheme:x?rotor=1"));
        QVERIFY(!none.link);
        QVERIFY2(none.error.contains(QStringLiteral("nosuchscheme")), qPrintable(none.error));
    }

    void theLineOpensOnceAndClosesWithTheLastRotor()
    {
        SharedLine line(QStringLiteral("testline:one"));
        TestLine *real = lastTestLine;
        QVERIFY(real);
        auto one = rotorLink(line, 1), two = rotorLink(line, 2);
        QSignalSpy oneOpened(one.get(), &Link::opened), twoOpened(two.get(), &Link::opened);
        one->open();
        two->open();
        QCOMPARE(real->opens, 1); // the second rotor waits for the same opening
        QCOMPARE(oneOpened.count(), 0);
        real->finishOpening();
        QCOMPARE(oneOpened.count(), 1);
        QCOMPARE(twoOpened.count(), 1);

        // A third rotor on an open line hears opened() after open() returns.
        auto three = rotorLink(line, 3);
        QSignalSpy threeOpened(three.get(), &Link::opened);
        three->open();
        QCOMPARE(threeOpened.count(), 0);
        QVERIFY(threeOpened.wait(1000));
        QCOMPARE(real->opens, 1);

        one->close();
        two.reset(); // destroyed while open: the same as closed
        QVERIFY(real->isOpen());
        three->close();
        QVERIFY(!real->isOpen()); // the last rotor gone: the line closes
    }

    void queriesTakeTurnsAndAnswersGoToWhoAsked()
    {
        SharedLine line(QStringLiteral("testline:one"));
        TestLine *real = lastTestLine;
        auto one = rotorLink(line, 1), two = rotorLink(line, 2);
        one->open();
        two->open();
        real->finishOpening();
        QList<QByteArray> &wire = real->far().written;

        one->setAwaitingReply(true);
        one->device()->write("C1\r");
        two->setAwaitingReply(true);
        two->device()->write("C2\r");
        QCOMPARE(wire, QList<QByteArray>{"C1\r"}); // rotor 2's query waits its turn
        QCOMPARE(line.queriesWaiting(), 1);

        // A stop never waits, whoever holds the wire.
        two->device()->write("S2\r");
        QCOMPARE(wire, (QList<QByteArray>{"C1\r", "S2\r"}));

        // The answer belongs to rotor 1, even though rotor 2 wrote last.
        QSignalSpy oneRead(one->device(), &QIODevice::readyRead);
        real->far().deliver("+0045\r");
        QVERIFY(oneRead.wait(1000));
        QCOMPARE(one->device()->readAll(), QByteArray("+0045\r"));
        QCOMPARE(two->device()->bytesAvailable(), 0);

        // Rotor 1 has its answer: rotor 2's query goes out, and its answer is its own.
        one->setAwaitingReply(false);
        QCOMPARE(wire.last(), QByteArray("C2\r"));
        QSignalSpy twoRead(two->device(), &QIODevice::readyRead);
        real->far().deliver("+0123\r");
        QVERIFY(twoRead.wait(1000));
        QCOMPARE(two->device()->readAll(), QByteArray("+0123\r"));
        QCOMPARE(one->device()->bytesAvailable(), 0);

        // A resend of an unanswered query keeps the wire; one given up frees it.
        two->setAwaitingReply(true);
        two->device()->write("C2\r");
        one->setAwaitingReply(true);
        one->device()->write("C1\r");
        two->setAwaitingReply(true);
        two->device()->write("C2\r");
        QCOMPARE(wire.mid(wire.size() - 2), (QList<QByteArray>{"C2\r", "C2\r"}));
        two->setAwaitingReply(false);
        QCOMPARE(wire.last(), QByteArray("C1\r"));

        // A rotor that closes with its query still waiting takes it along.
        two->setAwaitingReply(true);
        two->device()->write("C2\r");
        QCOMPARE(line.queriesWaiting(), 1);
        two->close();
        QCOMPARE(line.queriesWaiting(), 0);
        one->setAwaitingReply(false);
        QCOMPARE(wire.last(), QByteArray("C1\r"));

        // With no query on the wire, a refusal goes to the rotor that wrote last.
        one->device()->write("M400\r");
        QSignalSpy refusal(one->device(), &QIODevice::readyRead);
        real->far().deliver("?> M wants a bearing\r");
        QVERIFY(refusal.wait(1000));
        QCOMPARE(one->device()->readAll(), QByteArray("?> M wants a bearing\r"));
        QCOMPARE(line.bytesDropped(), 0);
    }

    void aLostLineIsLostForEveryRotor()
    {
        SharedLine line(QStringLiteral("testline:one"));
        TestLine *real = lastTestLine;
        auto one = rotorLink(line, 1), two = rotorLink(line, 2), three = rotorLink(line, 3);
        QSignalSpy oneLost(one.get(), &Link::lost), twoLost(two.get(), &Link::lost), threeFailed(three.get(), &Link::failed);
        one->open();
        two->open();
        real->finishOpening();
        one->setAwaitingReply(true);
        one->device()->write("C1\r");
        real->loseIt(QStringLiteral("cable pulled"));
        QCOMPARE(oneLost.count(), 1);
        QCOMPARE(twoLost.count(), 1);
        QCOMPARE(oneLost.first().at(0).toString(), QStringLiteral("cable pulled"));
        QVERIFY(!one->isOpen() && !two->isOpen());
        QCOMPARE(threeFailed.count(), 0); // never opened: nothing to lose

        // Each reopens in its own time; the line opens again once.
        one->open();
        two->open();
        QCOMPARE(real->opens, 2);
        real->finishOpening();
        QVERIFY(one->isOpen() && two->isOpen());
        // The query lost with the line does not hold the new wire.
        two->setAwaitingReply(true);
        two->device()->write("C2\r");
        QCOMPARE(real->far().written.last(), QByteArray("C2\r"));

        // A line that fails to open fails every rotor waiting for it.
        real->loseIt(QStringLiteral("gone"));
        three->open();
        emit real->failed(QStringLiteral("no such port"));
        QCOMPARE(threeFailed.count(), 1);
        QCOMPARE(threeFailed.first().at(0).toString(), QStringLiteral("no such port"));
    }

    void rotorsOutliveTheirLine()
    {
        std::unique_ptr<Link> one;
        {
            SharedLine line(QStringLiteral("testline:one"));
            one = rotorLink(line, 1);
            one->open();
            lastTestLine->finishOpening();
            QVERIFY(one->isOpen());
            // The line goes away first (a window closing): its rotors hear so.
        }
        QVERIFY(!one->isOpen());
        // Said from the event loop, not from inside the line's destructor.
        QSignalSpy lost(one.get(), &Link::lost);
        QCOMPARE(lost.count(), 0);
        QVERIFY(lost.wait(1000));
        QSignalSpy failed(one.get(), &Link::failed);
        one->open();
        QVERIFY(failed.wait(1000));
        QVERIFY2(failed.first().at(0).toString().contains(QStringLiteral("gone")), qPrintable(failed.first().at(0).toString()));
        one->device()->write("C1\r"); // nothing to write to, and no crash
    }

    void fourSessionsDriveFourRotorsOverOneLine()
    {
        SharedLine line(QStringLiteral("sim:?clock=manual&dialect=micro2g"));
        QVERIFY2(line.isValid(), qPrintable(line.error()));
        slew::sim::Simulator *sim = slew::sim::simulatorBehind(line.line());
        QVERIFY(sim);
        SimulatorPump pump;
        pump.drive(sim);

        std::array<std::unique_ptr<RotatorSession>, 4> sessions;
        int failedRequests = 0;
        for (int n = 1; n <= 4; ++n) {
            auto &s = sessions[size_t(n - 1)];
            s = std::make_unique<RotatorSession>();
            slew::model::RotatorProfile profile;
            profile.dialect = slew::protocol::Dialect::Micro2g;
            s->setProfile(profile);
            s->setLinkMaker([&line](const QString &uri) { return line.makeLink(uri); });
            QObject::connect(s.get(), &RotatorSession::requestFailed, s.get(), [&failedRequests](const QString &r, const QString &why) {
                qWarning("request %s failed: %s", qPrintable(r), qPrintable(why));
                ++failedRequests;
            });
            s->connectTo(QStringLiteral("sim:?clock=manual&dialect=micro2g&rotor=%1").arg(n));
        }
        auto allReady = [&] {
            for (auto &s : sessions) {
                if (!s->capabilities().probed || !s->hasPosition())
                    return false;
            }
            return true;
        };
        QVERIFY(runEventLoopUntil(allReady, 10000));
        for (int n = 1; n <= 4; ++n) {
            QCOMPARE(sessions[size_t(n - 1)]->rotor(), n);
            QVERIFY(sessions[size_t(n - 1)]->version().startsWith(QStringLiteral("Micro-2g")));
        }

        // Rotors 2 and 3 turn at once; each session sees its own rotor.
        QVERIFY(sessions[1]->gotoPosition(35, 0));
        QVERIFY(sessions[2]->gotoPosition(80, 0));
        using Drive = slew::sim::Micro2gController::Drive;
        QVERIFY(runEventLoopUntil([&] { return sim->micro2g().drive(2) != Drive::Off && sim->micro2g().drive(3) != Drive::Off; }, 5000));
        QVERIFY(runEventLoopUntil([&] {
            return sim->micro2g().drive(2) == Drive::Off && sim->micro2g().drive(3) == Drive::Off;
        }, 20000));
        // A poll or two later every session reads what the controller reads for its rotor.
        QVERIFY(runEventLoopUntil([&] {
            for (int n = 1; n <= 4; ++n) {
                const double heading = std::lround(sim->micro2g().heading(n)) % 360;
                if (sessions[size_t(n - 1)]->azimuth() != heading || sessions[size_t(n - 1)]->positionStale())
                    return false;
            }
            return true;
        }, 5000));
        QVERIFY(std::abs(sessions[1]->azimuth() - 35) <= 6.5);
        QVERIFY(std::abs(sessions[2]->azimuth() - 80) <= 6.5);
        QCOMPARE(sessions[0]->azimuth(), 0.0);
        QCOMPARE(sessions[3]->azimuth(), 0.0);

        // A stop on one rotor while the others poll: it stops that rotor only.
        QVERIFY(sessions[3]->gotoPosition(90, 0));
        QVERIFY(sessions[0]->gotoPosition(90, 0));
        QVERIFY(runEventLoopUntil([&] { return sim->micro2g().travel(4) > 10 && sim->micro2g().travel(1) > 10; }, 10000));
        QVERIFY(sessions[3]->stop(QStringLiteral("the test")));
        QVERIFY(runEventLoopUntil([&] { return sim->micro2g().drive(4) == Drive::Off; }, 1000));
        QVERIFY(sim->micro2g().drive(1) != Drive::Off);
        QVERIFY(sessions[0]->stop(QStringLiteral("the test")));

        // No answer went to the wrong rotor: nothing was left unanswered.
        QCOMPARE(failedRequests, 0);
        QCOMPARE(line.bytesDropped(), 0);
        QVERIFY(line.isOpen());

        for (auto &s : sessions)
            s->disconnectFromRotator();
        QVERIFY(!line.isOpen());
    }
};

QTEST_MAIN(SharedLineTest)
#include "tst_sharedline.moc"
