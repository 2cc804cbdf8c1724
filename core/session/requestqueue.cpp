#include "requestqueue.h"

namespace slew::session {

using protocol::Op;

bool Expectation::matches(const protocol::Message &m) const
{
    if (!m.hasValue && m.text.isEmpty() && m.op != Op::Alarm)
        return false; // a bare token is an echo of a query, not an answer
    const bool sameOp = m.op == op || (op == Op::ConfigRead && m.op == Op::ConfigValue);
    return sameOp && (index < 0 || m.index == index);
}

bool RequestQueue::push(Request r)
{
    if (isFull())
        return false;
    m_requests.push_back(std::move(r));
    return true;
}

bool RequestQueue::contains(const QByteArray &line) const
{
    for (const Request &r : m_requests) {
        if (r.line == line)
            return true;
    }
    return false;
}

bool RequestQueue::offer(const protocol::Message &m)
{
    Request *r = front();
    if (!r)
        return false;
    bool met = false;
    for (int i = 0; i < r->expectCount; ++i) {
        if (!(r->satisfied & (1u << i)) && r->expects[size_t(i)].matches(m)) {
            r->satisfied |= 1u << i;
            met = true;
            break;
        }
    }
    return met;
}

Request RequestQueue::takeFront()
{
    Request r = std::move(m_requests.front());
    m_requests.pop_front();
    return r;
}

void RequestQueue::failAll(const QString &reason)
{
    // Move out first: a callback may queue new work.
    std::deque<Request> failed;
    failed.swap(m_requests);
    for (Request &r : failed) {
        if (r.done)
            r.done(false, reason);
    }
}

} // namespace slew::session
