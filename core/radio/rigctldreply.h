// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One answer from rigctld, read a line at a time. Pure code.
//
// rigctld answers in one of two forms (the rigctld manual, "PROTOCOL"):
//
//   the default protocol        the extended response protocol (`+f`)
//   145800000                   get_freq:
//                               Frequency: 145800000
//                               RPRT 0
//   RPRT 0         (a set)      set_freq: 145800000
//                               RPRT 0
//   RPRT -11       (an error)   get_split_freq:
//                               RPRT -11
//
// The link asks in the extended form, whose answer always ends with RPRT
// and names its value, so nothing is left to counting lines. Both forms
// are understood: a rigctld-speaking program that ignores the `+` answers
// in the default one. The first line tells which: the command's long name
// and a colon, or not.
//
// A peer keeps to one form, so once the link has seen which, it says so:
// an answer in the other form is then a line out of place (an answer to a
// command before, a stray line), not an answer to this command. A get's
// `RPRT 0` with no value before it fits neither form.
//
// Only the value asked for is kept; other records (`Passband: 2400`) are
// passed over. An answer that fits no form, or runs past kMaxLines
// without its RPRT, is Broken: what follows it cannot be matched to
// commands any more.

#include <QByteArray>
#include <QByteArrayView>
#include <QString>

#include <optional>

namespace slew::radio {

class RigctldReply {
public:
    static constexpr int kMaxLines = 16;

    enum class Status { Incomplete, Complete, Broken };
    enum class Form { Either, Extended, Default };

    // `longName` as rigctld echoes it ("get_freq", "set_split_vfo");
    // `valueKey` the record a get answers with ("Frequency"), empty for a
    // set; `form` the one the peer answered in before, if known.
    RigctldReply(QByteArray longName, QByteArray valueKey, Form form = Form::Either);

    // One line as received, without its line end.
    Status take(QByteArrayView line);

    Status status() const { return m_status; }
    bool extended() const { return m_extended; }
    // The RPRT code (0: done; Hamlib errors are negative); 0 for a value in
    // the default form, which sends no RPRT on success.
    int code() const { return m_code; }
    // The text of the value asked for, when the answer held it.
    const std::optional<QString> &value() const { return m_value; }
    // Why the answer is Broken, in words for the operator.
    const QString &problem() const { return m_problem; }

private:
    Status broken(const QString &why);

    QByteArray m_longName;
    QByteArray m_valueKey;
    Form m_form;
    Status m_status = Status::Incomplete;
    bool m_started = false; // a line other than an empty one came
    bool m_extended = false;
    int m_lines = 0;
    int m_code = 0;
    std::optional<QString> m_value;
    QString m_problem;
};

} // namespace slew::radio
