#include "message.h"

#include <algorithm>
#include <cstring>

namespace slew::protocol {

bool InlineText::assign(QByteArrayView text)
{
    m_size = int(std::min<qsizetype>(text.size(), Capacity));
    if (m_size > 0)
        std::memcpy(m_data.data(), text.data(), size_t(m_size));
    return m_size == text.size();
}

Message Message::query(Op op, int index)
{
    Message m;
    m.op = op;
    m.index = index;
    return m;
}

Message Message::number(Op op, double value, int index)
{
    Message m;
    m.op = op;
    m.index = index;
    m.hasValue = true;
    m.value = value;
    return m;
}

Message Message::word(Op op, QByteArrayView text, int index)
{
    Message m;
    m.op = op;
    m.index = index;
    m.text.assign(text);
    return m;
}

Message Message::invalid(QByteArrayView raw, const char *reason, Refusal kind)
{
    Message m;
    m.op = Op::Invalid;
    m.text.assign(raw);
    m.reason = reason;
    m.refusal = kind;
    return m;
}

bool operator==(const Message &a, const Message &b)
{
    if (a.op != b.op || a.index != b.index || a.hasValue != b.hasValue || !(a.text == b.text))
        return false;
    if (a.hasValue && a.value != b.value)
        return false;
    if (a.op == Op::Encoders && a.encoders != b.encoders)
        return false;
    return true;
}

} // namespace slew::protocol
