// SPDX-License-Identifier: GPL-3.0-or-later
#include "descriptorset.h"

#include <QSocketNotifier>

#include <cerrno>
#include <sys/epoll.h>
#include <unistd.h>

namespace slew::transport {

namespace {

// Ready descriptors taken per turn of the event loop; the rest wait for the
// next, so a crowd of clients cannot starve the rest of the process.
constexpr int kEventsPerTurn = 64;

quint32 epollEvents(int events)
{
    return ((events & DescriptorSet::Readable) ? EPOLLIN : 0u) | ((events & DescriptorSet::Writable) ? EPOLLOUT : 0u);
}

} // namespace

DescriptorSet::DescriptorSet(QObject *parent) : QObject(parent), m_epoll(::epoll_create1(EPOLL_CLOEXEC))
{
    if (m_epoll < 0)
        return;
    m_notifier = std::make_unique<QSocketNotifier>(m_epoll, QSocketNotifier::Read);
    connect(m_notifier.get(), &QSocketNotifier::activated, this, &DescriptorSet::dispatch);
}

DescriptorSet::~DescriptorSet()
{
    m_notifier.reset();
    if (m_epoll >= 0)
        ::close(m_epoll);
}

quint64 DescriptorSet::add(int fd, int events, Handler handler)
{
    if (m_epoll < 0 || fd < 0)
        return 0;
    const quint64 key = m_nextKey++;
    epoll_event e{};
    e.events = epollEvents(events);
    e.data.u64 = key;
    if (::epoll_ctl(m_epoll, EPOLL_CTL_ADD, fd, &e) != 0)
        return 0;
    m_entries.insert(key, Entry{fd, events, std::make_shared<Handler>(std::move(handler))});
    return key;
}

void DescriptorSet::watch(quint64 key, int events)
{
    const auto it = m_entries.find(key);
    if (it == m_entries.end() || it->events == events)
        return;
    it->events = events;
    epoll_event e{};
    e.events = epollEvents(events);
    e.data.u64 = key;
    ::epoll_ctl(m_epoll, EPOLL_CTL_MOD, it->fd, &e);
}

void DescriptorSet::remove(quint64 key)
{
    const auto it = m_entries.find(key);
    if (it == m_entries.end())
        return;
    // Before the descriptor closes: a duplicate of it would keep it watched.
    ::epoll_ctl(m_epoll, EPOLL_CTL_DEL, it->fd, nullptr);
    m_entries.erase(it);
}

void DescriptorSet::dispatch()
{
    epoll_event ready[kEventsPerTurn];
    int n = 0;
    do {
        n = ::epoll_wait(m_epoll, ready, kEventsPerTurn, 0);
    } while (n < 0 && errno == EINTR);
    for (int i = 0; i < n; ++i) {
        const auto it = m_entries.constFind(ready[i].data.u64);
        if (it == m_entries.constEnd())
            continue; // removed by an earlier handler of this turn
        int events = 0;
        if (ready[i].events & (EPOLLIN | EPOLLHUP | EPOLLERR))
            events |= Readable;
        if (ready[i].events & (EPOLLOUT | EPOLLHUP | EPOLLERR))
            events |= Writable;
        events &= it->events;
        if (events == 0)
            continue;
        const std::shared_ptr<Handler> handler = it->handler;
        (*handler)(events);
    }
}

} // namespace slew::transport
