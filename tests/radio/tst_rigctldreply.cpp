// SPDX-License-Identifier: GPL-3.0-or-later
// rigctld's answers, a line at a time, in both of its forms, as rigctld
// 4.5.4 sends them and as a broken peer might.

#include "radio/rigctldreply.h"

#include <QTest>

using namespace slew::radio;

Q_DECLARE_METATYPE(slew::radio::RigctldReply::Status)
Q_DECLARE_METATYPE(slew::radio::RigctldReply::Form)

class RigctldReplyTest : public QObject {
    Q_OBJECT
private slots:
    void replyReader_data();
    void replyReader();
};

void RigctldReplyTest::replyReader_data()
{
    QTest::addColumn<QByteArray>("longName");
    QTest::addColumn<QByteArray>("key");
    QTest::addColumn<QByteArray>("lines");
    QTest::addColumn<RigctldReply::Status>("status");
    QTest::addColumn<int>("code");
    QTest::addColumn<QString>("value"); // "-": none
    QTest::addColumn<RigctldReply::Form>("form");
    using S = RigctldReply::Status;
    using F = RigctldReply::Form;
    // As rigctld 4.5.4 sends them.
    QTest::newRow("extended get") << QByteArray("get_freq") << QByteArray("Frequency")
                                  << QByteArray("get_freq:\nFrequency: 145800000\nRPRT 0") << S::Complete << 0 << "145800000" << F::Either;
    QTest::newRow("extended set") << QByteArray("set_freq") << QByteArray()
                                  << QByteArray("set_freq: 145800000\nRPRT 0") << S::Complete << 0 << "-" << F::Either;
    QTest::newRow("extended error") << QByteArray("get_split_freq") << QByteArray("TX Frequency")
                                    << QByteArray("get_split_freq:\nRPRT -11") << S::Complete << -11 << "-" << F::Either;
    QTest::newRow("other records passed over")
        << QByteArray("get_mode") << QByteArray("Mode") << QByteArray("get_mode:\nMode: FM\nPassband: 15000\nRPRT 0")
        << S::Complete << 0 << "FM" << F::Either;
    QTest::newRow("extended, carriage returns") << QByteArray("get_freq") << QByteArray("Frequency")
                                                << QByteArray("get_freq:\r\nFrequency: 7\r\nRPRT 0\r") << S::Complete << 0
                                                << "7" << F::Either;
    QTest::newRow("incomplete") << QByteArray("get_freq") << QByteArray("Frequency")
                                << QByteArray("get_freq:\nFrequency: 145800000") << S::Incomplete << 0 << "145800000" << F::Either;
    // The default form.
    QTest::newRow("default get") << QByteArray("get_freq") << QByteArray("Frequency") << QByteArray("145800000")
                                 << S::Complete << 0 << "145800000" << F::Either;
    QTest::newRow("default set") << QByteArray("set_freq") << QByteArray() << QByteArray("RPRT 0") << S::Complete << 0
                                 << "-" << F::Either;
    QTest::newRow("default error") << QByteArray("get_freq") << QByteArray("Frequency") << QByteArray("RPRT -9")
                                   << S::Complete << -9 << "-" << F::Either;
    // Broken.
    QTest::newRow("set answered with words") << QByteArray("set_freq") << QByteArray() << QByteArray("hello")
                                             << S::Broken << 0 << "-" << F::Either;
    QTest::newRow("RPRT without a number") << QByteArray("set_freq") << QByteArray() << QByteArray("RPRT nan")
                                           << S::Broken << 0 << "-" << F::Either;
    QTest::newRow("RPRT glued") << QByteArray("set_freq") << QByteArray() << QByteArray("RPRT0") << S::Broken << 0 << "-" << F::Either;
    QTest::newRow("two values") << QByteArray("get_freq") << QByteArray("Frequency")
                                << QByteArray("get_freq:\nFrequency: 1\nFrequency: 2\nRPRT 0") << S::Broken << 0 << "1" << F::Either;
    QTest::newRow("RPRT 0 where a value was due") << QByteArray("get_freq") << QByteArray("Frequency") << QByteArray("RPRT 0")
                                                  << S::Broken << 0 << "-" << F::Either;
    // Once the peer's form is known, the other one is a line out of place.
    QTest::newRow("extended expected, stray RPRT") << QByteArray("set_freq") << QByteArray() << QByteArray("RPRT 0")
                                                   << S::Broken << 0 << "-" << F::Extended;
    QTest::newRow("extended expected, a value") << QByteArray("get_freq") << QByteArray("Frequency")
                                                << QByteArray("145800000") << S::Broken << 0 << "-" << F::Extended;
    QTest::newRow("default expected, an echo") << QByteArray("set_freq") << QByteArray()
                                               << QByteArray("set_freq: 1\nRPRT 0") << S::Broken << 0 << "-" << F::Default;
    QTest::newRow("extended as expected") << QByteArray("set_freq") << QByteArray()
                                          << QByteArray("set_freq: 1\nRPRT -1") << S::Complete << -1 << "-" << F::Extended;
    QTest::newRow("default as expected") << QByteArray("get_freq") << QByteArray("Frequency") << QByteArray("7")
                                         << S::Complete << 0 << "7" << F::Default;
    QTest::newRow("no RPRT") << QByteArray("set_freq") << QByteArray()
                             << QByteArray("set_freq: 1\n") + QByteArray("x: y\n").repeated(20) << S::Broken << 0 << "-" << F::Either;
}

void RigctldReplyTest::replyReader()
{
    QFETCH(QByteArray, longName);
    QFETCH(QByteArray, key);
    QFETCH(QByteArray, lines);
    QFETCH(RigctldReply::Status, status);
    QFETCH(int, code);
    QFETCH(QString, value);
    QFETCH(RigctldReply::Form, form);
    RigctldReply reply(longName, key, form);
    for (const QByteArray &line : lines.split('\n'))
        reply.take(line);
    QCOMPARE(reply.status(), status);
    if (status == RigctldReply::Status::Broken)
        QVERIFY(!reply.problem().isEmpty());
    else
        QCOMPARE(reply.code(), code);
    QCOMPARE(reply.value().value_or(QStringLiteral("-")), value);
}

QTEST_GUILESS_MAIN(RigctldReplyTest)
#include "tst_rigctldreply.moc"
