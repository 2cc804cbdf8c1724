#pragma once
// Every line that goes to and comes from the controller, with the time, in a
// bounded buffer; a filter (regular expression, optionally inverted, per
// direction); and a line to send a raw Easycomm command through the session
// (which still checks it against the limits).

#include "session/rotatorsession.h"

#include <QDateTime>
#include <QRegularExpression>
#include <QTimer>
#include <QWidget>

#include <deque>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;

namespace slew::ui {

class TrafficConsole : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMaxEntries = 5000;
    static constexpr int kMaxPartialLine = 512; // a received line longer than this is cut

    explicit TrafficConsole(session::RotatorSession *session, QWidget *parent = nullptr);

    struct Entry {
        qint64 timeMs;
        bool sent;
        QByteArray line;
    };
    const std::deque<Entry> &entries() const { return m_entries; }
    static QString render(const Entry &e);

public slots:
    bool sendRaw(const QString &line);
    void clear();

private:
    void add(bool sent, const QByteArray &line);
    void onReceived(const QByteArray &bytes);
    bool matches(const Entry &e) const;
    void flushPending();
    void refilter();
    void followDialect(); // SPID takes binary frames, never a typed line

    session::RotatorSession *m_session;
    std::deque<Entry> m_entries;
    std::deque<Entry> m_pending; // not shown yet; the view is updated a few times a second
    QByteArray m_partial;
    qint64 m_partialTime = 0;
    QTimer m_flush;

    QPlainTextEdit *m_view;
    QLineEdit *m_filter;
    QCheckBox *m_invert;
    QCheckBox *m_showSent;
    QCheckBox *m_showReceived;
    QLineEdit *m_raw;
    QPushButton *m_send;
    QLabel *m_message;
    QRegularExpression m_pattern; // compiled from the filter field
};

} // namespace slew::ui
