#pragma once
// A file that records every line the simulator received, so a test can check
// what a real peer (Hamlib's rotctl) put on the wire. Unprintable bytes are
// written as \xNN so the file stays one line per received line.

#include <QByteArray>
#include <QFile>
#include <QString>

#include <optional>

namespace slew::sim {

class ReceivedLog {
public:
    // Opens (truncates) the file; false with error() on failure.
    bool open(const QString &path);
    QString error() const { return m_error; }
    bool isOpen() const { return m_file.isOpen(); }

    void writeLine(QByteArrayView line);

private:
    QFile m_file;
    QString m_error;
};

// Collects the bytes of one connection into lines for a ReceivedLog.
class LineCollector {
public:
    explicit LineCollector(ReceivedLog *log) : m_log(log) {}
    void add(QByteArrayView bytes);
    // Binary frames (SPID) have no line ends: a frame's last byte, kept,
    // ends its log line instead, so the log holds one frame a line.
    void endLinesAfter(char frameEnd) { m_frameEnd = frameEnd; }

private:
    static constexpr qsizetype maxLine = 512; // longer lines are logged in pieces
    ReceivedLog *m_log;
    QByteArray m_line;
    std::optional<char> m_frameEnd;
};

} // namespace slew::sim
