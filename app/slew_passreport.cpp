// SPDX-License-Identifier: GPL-3.0-or-later
// `slew --pass-report`: argument parsing and the file; the picture is
// drawn by slewui, the pass read by core/records. The options are
// described in cli/.

#include "slew_passreport.h"

#include "cli/argvoptions.h"
#include "cli/optionnames.h"
#include "cli/slewcommandline.h"
#include "slew_identity.h"

#include "history/passreportpicture.h"
#include "input/finitenumber.h"
#include "records/passrecordstore.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QGuiApplication>
#include <QSaveFile>

#include <climits>
#include <cstdio>

namespace opt = slew::cli::opt;

namespace {

int fail(int status, const QString &message)
{
    std::fprintf(stderr, "slew: %s\n", qPrintable(message));
    return status;
}

} // namespace

bool wantsPassReport(int argc, char **argv)
{
    return slew::cli::argvHasOption(argc, argv, opt::passReport);
}

int runPassReport(int argc, char **argv)
{
    // Drawn on an image: fonts need a GUI application, a display does not.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    setUpSlewApplication();
    QCommandLineParser parser;
    slew::cli::describeTo(parser, slew::cli::slewProgram(), slew::cli::slewPassReportMode());
    parser.process(app.arguments());

    QString why;
    const auto id = slew::input::wholeNumberIn(parser.value(opt::passReport), 1, INT_MAX, &why);
    if (!id)
        return fail(2, QStringLiteral("--pass-report: %1 (a pass's number, as the History tab lists it)").arg(why));
    const QString out = parser.value(opt::out).trimmed();
    if (out.isEmpty())
        return fail(2, QStringLiteral("--pass-report needs --out FILE.png"));
    QString error;
    const QString named = parser.value(opt::passDb).trimmed();
    if (parser.isSet(opt::passDb) && named.isEmpty())
        return fail(2, QStringLiteral("--pass-db: name a file"));
    const QString path = named.isEmpty() ? slew::records::PassRecordStore::defaultPath() : named;
    if (!QFileInfo::exists(path))
        return fail(1, QStringLiteral("no pass records at %1: no pass has been recorded there").arg(path));

    // Read only: the station service may be recording into it meanwhile.
    slew::records::PassRecordStore store;
    if (!store.open(path, slew::records::PassRecordStore::Access::Read, &error))
        return fail(2, error);
    const std::optional<slew::records::PassRecord> pass = store.pass(*id);
    if (!pass)
        return fail(1, QStringLiteral("no pass %1 in %2; nothing written").arg(*id).arg(path));
    int skipped = 0;
    const QList<slew::records::PassSample> samples = store.samples(*id, &skipped);
    if (samples.isEmpty())
        return fail(1, QStringLiteral("pass %1 (%2, %3) has no samples to draw%4; nothing written")
                           .arg(*id)
                           .arg(pass->planned.target, slew::records::outcomeName(pass->outcome),
                                pass->outcome == slew::records::Outcome::Dropped
                                    ? QStringLiteral(": a dropped pass is not tracked")
                                    : QStringLiteral(" (samples are kept %1 days)")
                                          .arg(slew::records::PassRecordStore::kDefaultKeepDays)));

    const QImage picture = slew::ui::renderPassReport(*pass, samples);
    // Whole or not at all: a failed write leaves no half picture.
    QSaveFile file(out);
    if (!file.open(QIODevice::WriteOnly) || !picture.save(&file, "PNG") || !file.commit())
        return fail(2, QStringLiteral("%1 cannot be written: %2").arg(out, file.errorString()));
    std::printf("pass %lld (%s, %s): %s, %dx%d, %lld samples%s\n", qint64(*id), qPrintable(pass->planned.target),
                qPrintable(slew::records::outcomeName(pass->outcome)), qPrintable(out), picture.width(),
                picture.height(), qint64(samples.size()),
                skipped > 0 ? qPrintable(QStringLiteral(" (%1 unreadable left out)").arg(skipped)) : "");
    return 0;
}
