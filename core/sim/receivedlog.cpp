#include "receivedlog.h"

namespace slew::sim {

bool ReceivedLog::open(const QString &path)
{
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered)) {
        m_error = QStringLiteral("cannot write %1: %2").arg(path, m_file.errorString());
        return false;
    }
    return true;
}

void ReceivedLog::writeLine(QByteArrayView line)
{
    if (!m_file.isOpen())
        return;
    QByteArray text;
    text.reserve(line.size() + 1);
    for (char c : line) {
        const auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7f && c != '\\') {
            text += c;
        } else {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", u);
            text += hex;
        }
    }
    text += '\n';
    m_file.write(text);
}

void LineCollector::add(QByteArrayView bytes)
{
    if (!m_log)
        return;
    for (char c : bytes) {
        if (c == '\n' || c == '\r') {
            if (!m_line.isEmpty())
                m_log->writeLine(m_line);
            m_line.clear();
            continue;
        }
        m_line += c;
        if (m_line.size() >= maxLine || c == m_frameEnd) {
            m_log->writeLine(m_line);
            m_line.clear();
        }
    }
}

} // namespace slew::sim
