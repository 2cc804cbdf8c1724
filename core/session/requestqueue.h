#pragma once
// The queries waiting for the controller, oldest first.
//
// Easycomm replies carry no tag, so only one query is on the wire at a time
// and a reply is matched by what it is: `AZ EL` is answered by an azimuth and
// an elevation, `CR1` by `CR1,…` or SatNOGS' bare `1,…`. The queue is bounded:
// a controller that stops answering must not make it grow.

#include "protocol/message.h"

#include <QByteArray>
#include <QString>

#include <array>
#include <deque>
#include <functional>

namespace slew::session {

enum class RequestPurpose : std::uint8_t { Position, Telemetry, Probe, User, KeepAlive };

struct Expectation {
    protocol::Op op = protocol::Op::Invalid;
    int index = -1; // -1: any
    bool matches(const protocol::Message &m) const;
};

struct Request {
    QByteArray line;        // what goes on the wire, with its terminator
    std::array<Expectation, 2> expects{};
    int expectCount = 0;
    int attemptsLeft = 1;
    RequestPurpose purpose = RequestPurpose::User;
    // Called once: ok, or the reason it failed.
    std::function<void(bool ok, const QString &reason)> done;

    // Filled in while on the wire.
    unsigned satisfied = 0; // bit per expectation
    bool complete() const { return satisfied == (1u << expectCount) - 1; }
};

class RequestQueue {
public:
    explicit RequestQueue(int capacity = 64) : m_capacity(capacity) {}

    // A smaller capacity keeps what is already queued; it only refuses more.
    void setCapacity(int capacity) { m_capacity = capacity; }
    bool isFull() const { return int(m_requests.size()) >= m_capacity; }
    bool isEmpty() const { return m_requests.empty(); }
    int size() const { return int(m_requests.size()); }

    // False (and nothing added) when full.
    bool push(Request r);
    // Whether a request with this exact line is waiting or on the wire, so
    // that a slow controller does not collect duplicate polls.
    bool contains(const QByteArray &line) const;

    Request *front() { return m_requests.empty() ? nullptr : &m_requests.front(); }
    // Marks the expectations of the front request that `m` meets; true when
    // it did meet one.
    bool offer(const protocol::Message &m);
    Request takeFront();

    // Fails every request with the reason, oldest first, and empties the queue.
    void failAll(const QString &reason);

private:
    std::deque<Request> m_requests;
    int m_capacity;
};

} // namespace slew::session
