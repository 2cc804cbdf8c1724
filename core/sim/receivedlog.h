#pragma once
// A file that records every line the simulator received, so a test can check
// what a real peer (Hamlib's rotctl) put on the wire. Unprintable bytes are
// written as \xNN so the file stays one line per received line.

#include <QByteArray>
#include <QFile>
#include <QString>

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

private:
    static constexpr qsizetype maxLine = 512; // longer lines are logged in pieces
    ReceivedLog *m_log;
    QByteArray m_line;
};

} // namespace slew::sim
