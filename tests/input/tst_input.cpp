// SPDX-License-Identifier: GPL-3.0-or-later
// The one rule for numbers from outside, and the bounded reader of files a
// user names: tables of texts that must be refused and kept, and real
// devices, FIFOs and directories.

#include "input/boundedfile.h"
#include "input/finitenumber.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <limits>
#include <sys/stat.h>
#include <sys/types.h>

using namespace slew::input;

class TestInput : public QObject {
    Q_OBJECT

private slots:
    void finiteNumbersAreRead_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("accepted");
        QTest::addColumn<double>("value");
        QTest::newRow("integer") << "42" << true << 42.0;
        QTest::newRow("spaces") << "  -5.25 " << true << -5.25;
        QTest::newRow("exponent") << "1.5e3" << true << 1500.0;
        QTest::newRow("nan") << "nan" << false << 0.0;
        QTest::newRow("NaN") << "NaN" << false << 0.0;
        QTest::newRow("-nan") << "-nan" << false << 0.0;
        QTest::newRow("inf") << "inf" << false << 0.0;
        QTest::newRow("-inf") << "-inf" << false << 0.0;
        QTest::newRow("infinity") << "infinity" << false << 0.0;
        QTest::newRow("overflow") << "1e999" << false << 0.0;
        QTest::newRow("empty") << "" << false << 0.0;
        QTest::newRow("trailing letters") << "12abc" << false << 0.0;
        QTest::newRow("two numbers") << "1 2" << false << 0.0;
        // As element sets write them: no leading zero, a capital E, a plus.
        QTest::newRow("no leading zero") << ".0004569" << true << 0.0004569;
        QTest::newRow("negative, no leading zero") << "-.11606E-4" << true << -0.11606e-4;
        QTest::newRow("plus") << "+1.5" << true << 1.5;
        QTest::newRow("two signs") << "+-1.5" << false << 0.0;
        QTest::newRow("point last") << "5." << true << 5.0;
        QTest::newRow("point alone") << "." << false << 0.0;
        QTest::newRow("underflow, refused as Qt refuses it") << "1e-400" << false << 0.0;
        QTest::newRow("hex") << "0x10" << false << 0.0;
        QTest::newRow("longer than the fast path") << QString(100, u'0') + QStringLiteral("1.5") << true << 1.5;
        QTest::newRow("not ASCII digits") << QString::fromUtf8("\u0661") << false << 0.0;
        QTest::newRow("nearest double") << "0.1" << true << 0.1;
    }
    void finiteNumbersAreRead()
    {
        QFETCH(QString, text);
        QFETCH(bool, accepted);
        QFETCH(double, value);
        const std::optional<double> read = finiteNumber(text);
        QCOMPARE(read.has_value(), accepted);
        if (accepted)
            QCOMPARE(*read, value);
    }

    // Plain decimals of up to 15 digits are read by a division of their own:
    // it must give the very double std::from_chars gives, bit for bit, for
    // every length and place of the point, and leave longer texts alone.
    void plainDecimalsAreTheNearestDouble()
    {
        std::uint64_t state = 0x2545f4914f6cdd1dULL;
        const auto next = [&state] {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            return state;
        };
        for (int i = 0; i < 200000; ++i) {
            const int digits = 1 + int(next() % 17);
            std::string text = (next() & 1) ? "-" : "";
            const int point = int(next() % (digits + 1));
            for (int d = 0; d < digits; ++d) {
                if (d == point)
                    text += '.';
                text += char('0' + next() % 10);
            }
            double expected = 0;
            std::from_chars(text.c_str(), text.c_str() + text.size(), expected);
            const std::optional<double> read = finiteNumber(QString::fromStdString(text));
            QVERIFY2(read.has_value(), text.c_str());
            QVERIFY2(std::signbit(*read) == std::signbit(expected) && *read == expected, text.c_str());
        }
    }

    void rangesRefuseNanAndSayWhy()
    {
        const NumberRange elevation{-5, 90, "°"};
        QString why;
        QVERIFY(!numberIn(u"nan", elevation, &why));
        QCOMPARE(why, QStringLiteral("'nan' is not a finite number"));
        QVERIFY(!numberIn(u"inf", elevation, &why));
        QCOMPARE(why, QStringLiteral("'inf' is not a finite number"));
        QVERIFY(!numberIn(u"91", elevation, &why));
        QCOMPARE(why, QStringLiteral("91° is outside -5..90°"));
        QVERIFY(!numberIn(u"ten", elevation, &why));
        QCOMPARE(why, QStringLiteral("'ten' is not a number"));
        QCOMPARE(numberIn(u"-5", elevation, &why).value_or(-1), -5.0);
        QCOMPARE(numberIn(u"90", elevation, &why).value_or(-1), 90.0);

        QVERIFY(!elevation.contains(std::numeric_limits<double>::quiet_NaN()));
        QVERIFY(!elevation.contains(std::numeric_limits<double>::infinity()));
        QVERIFY(!checkNumber(std::numeric_limits<double>::quiet_NaN(), elevation, &why));
        QCOMPARE(why, QStringLiteral("nan is not a finite number"));
        QVERIFY(allFinite(1.0, 2, -3.5f));
        QVERIFY(!allFinite(1.0, std::numeric_limits<double>::quiet_NaN()));
        QVERIFY(!allFinite(std::numeric_limits<double>::infinity()));
    }

    void refusalsQuoteControlCharactersEscaped()
    {
        QString why;
        QVERIFY(!numberIn(QString::fromLatin1("\x1b[2J\x07"), NumberRange{0, 1}, &why));
        QVERIFY2(!why.contains(QChar(0x1b)) && why.contains(QStringLiteral("\\x1b")), qPrintable(why));
    }

    void wholeNumbers()
    {
        QString why;
        QCOMPARE(wholeNumberIn(u"4533", 1, 65535, &why).value_or(-1), 4533);
        QVERIFY(!wholeNumberIn(u"70000", 1, 65535, &why));
        QCOMPARE(why, QStringLiteral("70000 is outside 1..65535"));
        QVERIFY(!wholeNumberIn(u"4.5", 1, 10, &why));
        QVERIFY(!wholeNumberIn(u"99999999999", 1, 10, &why));
    }

    void regularFilesAreReadWhole()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("small.txt"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(1000, 'x'));
        f.close();
        const BoundedRead read = readBoundedFile(path, 1000);
        QVERIFY2(read.ok(), qPrintable(read.error));
        QCOMPARE(read.bytes.size(), 1000);

        const BoundedRead over = readBoundedFile(path, 999);
        QVERIFY(!over.ok());
        QVERIFY(over.bytes.isEmpty());
        QCOMPARE(over.error, path + QStringLiteral(" is over the 999 bytes limit for this file"));
    }

    void devicesAreRefusedWithoutReading()
    {
        QElapsedTimer t;
        t.start();
        const BoundedRead zero = readBoundedFile(QStringLiteral("/dev/zero"), 64 * 1024);
        QVERIFY(!zero.ok());
        QCOMPARE(zero.error, QStringLiteral("/dev/zero is a character device, not a file; name a regular file"));
        QVERIFY(zero.bytes.isEmpty());
        QVERIFY(t.elapsed() < 1000);
    }

    void fifosAreRefusedWithoutBlocking()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("fifo"));
        QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        // No writer: a blocking open() would wait here forever.
        const BoundedRead read = readBoundedFile(path, 64 * 1024);
        QVERIFY(!read.ok());
        QVERIFY2(read.error.contains(QStringLiteral("a FIFO (named pipe), not a file")), qPrintable(read.error));
    }

    void directoriesAndMissingFilesAreRefused()
    {
        QTemporaryDir dir;
        const BoundedRead directory = readBoundedFile(dir.path(), 1024);
        QVERIFY(!directory.ok());
        QVERIFY2(directory.error.contains(QStringLiteral("is a directory")), qPrintable(directory.error));
        const BoundedRead missing = readBoundedFile(dir.filePath(QStringLiteral("none")), 1024);
        QVERIFY(!missing.ok());
        QVERIFY2(missing.error.contains(QStringLiteral("No such file")), qPrintable(missing.error));
        QVERIFY(!readBoundedFile(QString(), 10).ok());
    }

    void capsAreStatedPlainly()
    {
        QCOMPARE(byteSizeText(64 * 1024), QStringLiteral("64 KiB"));
        QCOMPARE(byteSizeText(16 * 1024 * 1024), QStringLiteral("16 MiB"));
        QCOMPARE(byteSizeText(1000), QStringLiteral("1000 bytes"));
    }
};

QTEST_GUILESS_MAIN(TestInput)
#include "tst_input.moc"
