// SPDX-License-Identifier: GPL-3.0-or-later
// The MQTT client against a real Mosquitto of the test's own (TLS with a
// generated authority, accounts, an access list), with mosquitto_pub and
// mosquitto_sub as the other peers: it connects, publishes and receives; the
// broker's refusals (a wrong password, a certificate from another
// authority, a publish the access list denies) come back in words; a broker
// that goes away is found again; and a broker that never answers never
// holds up the event loop.

#include "../common/mosquittobroker.h"

#include "remote/mqttclient.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTest>
#include <QTimer>

using slew::remote::MqttClient;
using slew::remote::MqttMessage;
using slew::remote::MqttSettings;
using slew::remote::parseBrokerAddress;

namespace {

MqttSettings settingsFor(const MosquittoBroker &broker, const QString &user, const QString &password = {})
{
    MqttSettings s;
    QString error;
    s.broker = *parseBrokerAddress(broker.url(user), &error);
    s.password = password.isEmpty() ? MosquittoBroker::password(user) : password;
    return s;
}

// The longest the event loop went without turning while `running` held.
qint64 longestStall(const std::function<bool()> &done, int ms)
{
    QElapsedTimer since;
    qint64 longest = 0;
    QTimer tick;
    tick.setInterval(5);
    QObject::connect(&tick, &QTimer::timeout, [&] {
        longest = std::max(longest, since.restart());
    });
    since.start();
    tick.start();
    (void)QTest::qWaitFor(done, ms);
    return longest;
}

} // namespace

class MqttClientTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QString error;
        QVERIFY2(m_broker.start(&error), qPrintable(error));
    }

    void connectsPublishesAndReceives()
    {
        MqttClient client(settingsFor(m_broker, QStringLiteral("station-mast")));
        QSignalSpy connected(&client, &MqttClient::connected);
        QSignalSpy received(&client, &MqttClient::messageReceived);
        client.subscribe(QStringLiteral("slew/mast/command"));
        QString error;
        QVERIFY2(client.open(&error), qPrintable(error));
        QVERIFY2(connected.wait(15000), qPrintable(client.problem() + m_broker.log()));
        QVERIFY(client.isConnected());

        // A retained message, as mosquitto_sub sees it.
        MosquittoSubscriber watcher(m_broker, QStringLiteral("watcher"), {QStringLiteral("slew/mast/state")});
        QVERIFY(client.publish({QStringLiteral("slew/mast/state"), "{\"hello\":1}", 1, true}));
        QVERIFY2(watcher.waitFor(QStringLiteral("slew/mast/state"), [](const QByteArray &p) { return p == "{\"hello\":1}"; }),
                 watcher.errors().constData());

        // An operator's command reaches the station (the subscription was
        // made once connected).
        QTRY_VERIFY_WITH_TIMEOUT(
            m_broker.publish(QStringLiteral("operator"), QStringLiteral("slew/mast/command"), "{\"cmd\":\"stop\"}").exitCode == 0
                && received.size() > 0,
            15000);
        QCOMPARE(received.first().at(0).toString(), QStringLiteral("slew/mast/command"));
        QCOMPARE(received.first().at(1).toByteArray(), QByteArray("{\"cmd\":\"stop\"}"));

        QSignalSpy closed(&client, &MqttClient::closed);
        client.close(MqttMessage{QStringLiteral("slew/mast/state"), "{}", 1, true});
        QVERIFY(closed.wait(5000));
        QVERIFY(watcher.waitFor(QStringLiteral("slew/mast/state"), [](const QByteArray &p) { return p == "{}"; }));
    }

    void wrongPasswordIsRefusedInWords()
    {
        MqttClient client(settingsFor(m_broker, QStringLiteral("operator"), QStringLiteral("not-the-password")));
        QSignalSpy lost(&client, &MqttClient::connectionLost);
        QSignalSpy connected(&client, &MqttClient::connected);
        QString error;
        QVERIFY(client.open(&error));
        QVERIFY(lost.wait(15000));
        QVERIFY2(lost.first().at(0).toString().contains(QStringLiteral("refused")), qPrintable(lost.first().at(0).toString()));
        QVERIFY2(lost.first().at(0).toString().contains(QStringLiteral("user name or password"), Qt::CaseInsensitive)
                     || lost.first().at(0).toString().contains(QStringLiteral("authori"), Qt::CaseInsensitive),
                 qPrintable(lost.first().at(0).toString()));
        QCOMPARE(lost.first().at(1).toInt(), 1); // tried again after a second, then longer
        QCOMPARE(connected.size(), 0);
        QCOMPARE(client.state(), MqttClient::State::Reconnecting);
    }

    void certificateFromAnotherAuthorityIsRefused()
    {
        // No cafile: the system's authorities, which never signed the test's.
        MqttSettings s = settingsFor(m_broker, QStringLiteral("operator"));
        s.broker.caFile.clear();
        MqttClient client(s);
        QSignalSpy lost(&client, &MqttClient::connectionLost);
        QSignalSpy connected(&client, &MqttClient::connected);
        QString error;
        QVERIFY(client.open(&error));
        QVERIFY(lost.wait(15000));
        QVERIFY2(lost.first().at(0).toString().contains(QStringLiteral("TLS")), qPrintable(lost.first().at(0).toString()));
        QCOMPARE(connected.size(), 0);
    }

    void missingCaFileIsRefusedAtOnce()
    {
        MqttSettings s = settingsFor(m_broker, QStringLiteral("operator"));
        s.broker.caFile = QStringLiteral("/nonexistent/ca.pem");
        MqttClient client(s);
        QString error;
        QVERIFY(!client.open(&error));
        QVERIFY2(error.contains(QStringLiteral("/nonexistent/ca.pem")), qPrintable(error));
    }

    void theAccessListRefusesAWatchersPublish()
    {
        MqttClient client(settingsFor(m_broker, QStringLiteral("watcher")));
        QSignalSpy connected(&client, &MqttClient::connected);
        QSignalSpy refused(&client, &MqttClient::publishRefused);
        QString error;
        QVERIFY(client.open(&error));
        QVERIFY(connected.wait(15000));
        int mid = 0;
        QVERIFY(client.publish({QStringLiteral("slew/mast/command"), "{\"cmd\":\"goto\",\"az\":1,\"el\":1}", 1, false}, &mid));
        QVERIFY(refused.wait(10000));
        QCOMPARE(refused.first().at(0).toInt(), mid);
        QVERIFY2(refused.first().at(1).toString().contains(QStringLiteral("authori"), Qt::CaseInsensitive),
                 qPrintable(refused.first().at(1).toString()));
    }

    void findsTheBrokerAgainAfterItWentAway()
    {
        MosquittoBroker broker;
        QString error;
        QVERIFY2(broker.start(&error), qPrintable(error));
        MqttClient client(settingsFor(broker, QStringLiteral("station-mast")));
        QSignalSpy connected(&client, &MqttClient::connected);
        QSignalSpy lost(&client, &MqttClient::connectionLost);
        QVERIFY(client.open(&error));
        QVERIFY(connected.wait(15000));
        // stop() and start() wait for the broker's process in an event loop
        // of their own, and the client may hear of the loss (or connect
        // again) while they do: a spy's wait() would then wait for a second
        // one. Count instead (seen on a loaded fresh Debian 12).
        broker.stop();
        QTRY_VERIFY_WITH_TIMEOUT(lost.size() >= 1, 15000);
        QCOMPARE(client.state(), MqttClient::State::Reconnecting);
        // The same broker back on the same port: found again by the backoff.
        QVERIFY2(broker.start(&error, broker.port(), broker.plainPort()), qPrintable(error));
        QTRY_VERIFY2_WITH_TIMEOUT(connected.size() >= 2, qPrintable(client.problem()), 30000);
        QCOMPARE(connected.size(), 2);
    }

    void aBrokerThatNeverAnswersNeverHoldsTheEventLoop()
    {
        // Takes the connection and says nothing: no TLS handshake, no CONNACK.
        QTcpServer silent;
        QVERIFY(silent.listen(QHostAddress::LocalHost, 0));
        MqttSettings s = settingsFor(m_broker, QStringLiteral("operator"));
        s.broker.port = silent.serverPort();
        s.connectTimeoutMs = 1500;
        MqttClient client(s);
        QSignalSpy lost(&client, &MqttClient::connectionLost);
        QString error;
        QElapsedTimer opening;
        opening.start();
        QVERIFY(client.open(&error));
        QVERIFY(opening.elapsed() < 100); // open() itself returns at once
        const qint64 stall = longestStall([&] { return lost.size() >= 2; }, 20000);
        QCOMPARE(lost.size(), 2);
        QVERIFY2(lost.first().at(0).toString().contains(QStringLiteral("no answer")), qPrintable(lost.first().at(0).toString()));
        // Ticks every 5 ms went on all along; a loaded machine may delay one.
        QVERIFY2(stall < 250, qPrintable(QString::number(stall)));
        // Closing while it waits returns at once too.
        QElapsedTimer closing;
        closing.start();
        QSignalSpy closed(&client, &MqttClient::closed);
        client.close();
        QVERIFY(closed.wait(5000));
        QVERIFY2(closing.elapsed() < 1000, qPrintable(QString::number(closing.elapsed())));
    }

private:
    MosquittoBroker m_broker;
};

QTEST_GUILESS_MAIN(MqttClientTest)
#include "tst_mqttclient.moc"
