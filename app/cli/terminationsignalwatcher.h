#pragma once
// Turns SIGINT and SIGTERM into a Qt signal, so a server can stop cleanly
// from its event loop. The handler only writes a byte to a socket pair (the
// one thing that is safe there); a QSocketNotifier picks it up.

#include <QObject>

#include <memory>

class QSocketNotifier;

namespace slew::cli {

class TerminationSignalWatcher : public QObject {
    Q_OBJECT
public:
    explicit TerminationSignalWatcher(QObject *parent = nullptr);
    ~TerminationSignalWatcher() override;

    bool isValid() const { return m_notifier != nullptr; }

signals:
    void terminationRequested(int signalNumber);

private:
    void drain();
    std::unique_ptr<QSocketNotifier> m_notifier;
};

} // namespace slew::cli
