// SPDX-License-Identifier: GPL-3.0-or-later
// The XOR checksum frame Slew defines for the easycom library's optional
// checksum (docs/protocol.md, "Checksum"): framing, checking, and the line
// reader that sits before the parser on a checksummed link.

#include "protocol/checksum.h"

#include <QTest>

#include <utility>
#include <vector>

using namespace slew::protocol;

namespace {

// Every line the reader hands out, as (verdict, bytes).
std::vector<std::pair<FrameCheck, QByteArray>> readAll(QByteArrayView bytes, ChecksumReader &reader)
{
    std::vector<std::pair<FrameCheck, QByteArray>> out;
    reader.feed(bytes, [&](FrameCheck c, QByteArrayView line) { out.emplace_back(c, line.toByteArray()); });
    return out;
}

} // namespace

class ChecksumTest : public QObject {
    Q_OBJECT
private slots:
    void xorOfTheLine()
    {
        QCOMPARE(xorChecksum(""), std::uint8_t(0));
        QCOMPARE(xorChecksum("A"), std::uint8_t(0x41));
        // 'A'^'Z'^' '^'E'^'L' = 0x41^0x5A^0x20^0x45^0x4C
        QCOMPARE(xorChecksum("AZ EL"), std::uint8_t(0x41 ^ 0x5A ^ 0x20 ^ 0x45 ^ 0x4C));
    }

    void framesEveryLineBeforeItsTerminator()
    {
        QCOMPARE(withChecksums("AZ EL\n"), QByteArray("AZ EL*32\n"));
        QCOMPARE(withChecksums("C2\r"), QByteArray("C2*71\r"));
        // GS-232 answers end CR LF: the LF is an empty line and stays bare.
        QCOMPARE(withChecksums("+0010+0020\r\n"), QByteArray("+0010+0020*03\r\n"));
        // Several lines, and a last one without a terminator.
        QCOMPARE(withChecksums("S\rC2"), QByteArray("S*53\rC2*71"));
        QCOMPARE(withChecksums(""), QByteArray());
    }

    void checksGoodLines()
    {
        QByteArrayView payload;
        QCOMPARE(checkLine("AZ EL*32", &payload), FrameCheck::Good);
        QCOMPARE(payload, QByteArrayView("AZ EL"));
        // Lower-case hex is read too.
        QCOMPARE(checkLine("AZ*1b", &payload), FrameCheck::Good); // 'A' ^ 'Z' = 0x1B
        QCOMPARE(payload, QByteArrayView("AZ"));
        QCOMPARE(checkLine("AZ*1B", nullptr), FrameCheck::Good);
        QCOMPARE(withChecksums("AZ\n"), QByteArray("AZ*1B\n")); // written upper case
    }

    void refusesCorruptedAndMissing()
    {
        QCOMPARE(checkLine("AZ EL*33", nullptr), FrameCheck::Bad);       // wrong sum
        QCOMPARE(checkLine("AZ EM*32", nullptr), FrameCheck::Bad);       // one bit of the payload flipped
        QCOMPARE(checkLine("AZ EL*3G", nullptr), FrameCheck::Bad);       // not hex
        QCOMPARE(checkLine("AZ EL", nullptr), FrameCheck::Missing);      // none
        QCOMPARE(checkLine("AZ EL*3", nullptr), FrameCheck::Missing);    // one digit: no frame where it belongs
        QCOMPARE(checkLine("AZ EL*32 ", nullptr), FrameCheck::Missing);  // not right before the terminator
        QCOMPARE(checkLine("", nullptr), FrameCheck::Missing);
        QCOMPARE(checkLine("*00", nullptr), FrameCheck::Good);           // an empty payload checks; the parser has nothing to read
    }

    void readerHandsGoodLinesOnWithTheirTerminator()
    {
        ChecksumReader reader;
        const auto lines = readAll("AZ EL*32\nC2*71\r\n", reader);
        QCOMPARE(lines.size(), size_t(2));
        QCOMPARE(lines[0].first, FrameCheck::Good);
        QCOMPARE(lines[0].second, QByteArray("AZ EL\n"));
        QCOMPARE(lines[1].second, QByteArray("C2\r"));
        QVERIFY(!reader.hasUnfinishedLine());
    }

    void readerIsTheSameByteByByte()
    {
        const QByteArray stream = "AZ EL*32\nAZ EL*33\nGS\n" + withChecksums("VE\n");
        ChecksumReader whole, bytewise;
        const auto a = readAll(stream, whole);
        std::vector<std::pair<FrameCheck, QByteArray>> b;
        for (char c : stream) {
            for (auto &l : readAll(QByteArrayView(&c, 1), bytewise))
                b.push_back(std::move(l));
        }
        QCOMPARE(a, b);
        QCOMPARE(a.size(), size_t(4));
        QCOMPARE(a[1].first, FrameCheck::Bad);
        QCOMPARE(a[1].second, QByteArray("AZ EL*33")); // the raw line, for the message
        QCOMPARE(a[2].first, FrameCheck::Missing);
        QCOMPARE(a[3].second, QByteArray("VE\n"));
    }

    void overlongLinesAreDroppedOnceAndTheReaderResyncs()
    {
        ChecksumReader reader;
        const QByteArray longLine = withChecksums(QByteArray(ChecksumReader::Capacity + 10, 'A') + '\n');
        const auto lines = readAll(longLine + withChecksums("AZ\n"), reader);
        QCOMPARE(lines.size(), size_t(2));
        QCOMPARE(lines[0].first, FrameCheck::Overlong);
        QCOMPARE(lines[1].first, FrameCheck::Good);
        QCOMPARE(lines[1].second, QByteArray("AZ\n"));
        // Exactly at capacity still fits.
        const QByteArray full = QByteArray(ChecksumReader::Capacity - 3, 'B');
        const auto fits = readAll(withChecksums(full + '\n'), reader);
        QCOMPARE(fits.size(), size_t(1));
        QCOMPARE(fits[0].first, FrameCheck::Good);
    }
};

QTEST_APPLESS_MAIN(ChecksumTest)
#include "tst_checksum.moc"
