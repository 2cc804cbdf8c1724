// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Many descriptors watched behind one QSocketNotifier, through epoll.
//
// Qt's event loop polls the descriptor of every enabled notifier on every
// turn, and walks all of them again to see which woke it: with many clients
// connected each turn costs in proportion, although one of them asked. An
// epoll set stands for all of them in that poll; when it wakes the loop,
// epoll says which are ready, and only their handlers run. Level-triggered,
// as notifiers are: what is left unread is reported again on the next turn.

#include <QHash>
#include <QObject>

#include <functional>
#include <memory>

class QSocketNotifier;

namespace slew::transport {

class DescriptorSet : public QObject {
    Q_OBJECT
public:
    enum Event { Readable = 1, Writable = 2 };
    // The events that are ready (a hang-up or an error reads as both: the
    // handler finds out which by reading or writing).
    using Handler = std::function<void(int events)>;

    explicit DescriptorSet(QObject *parent = nullptr);
    ~DescriptorSet() override;
    bool isValid() const { return m_epoll >= 0; }

    // Watches `fd` for `events`: a key for the calls below, 0 on a failure.
    quint64 add(int fd, int events, Handler handler);
    void watch(quint64 key, int events);
    // Forgets it; an event already collected for it is dropped. Callable
    // from any handler, its own included.
    void remove(quint64 key);

private:
    void dispatch();

    struct Entry {
        int fd = -1;
        int events = 0;
        std::shared_ptr<Handler> handler; // kept alive while it runs
    };
    int m_epoll = -1;
    std::unique_ptr<QSocketNotifier> m_notifier;
    QHash<quint64, Entry> m_entries;
    quint64 m_nextKey = 1; // never reused: a late event finds nobody
};

} // namespace slew::transport
