// SPDX-License-Identifier: GPL-3.0-or-later
#include "tracking/elementsetsdialog.h"

#include "widgets/filechooser.h"

#include "input/finitenumber.h"

#include "tracking/elementsetages.h"

#include "sky/skyvector.h"
#include "sky/elementsetsources.h"
#include "sky/utctime.h"

#include <QDateTime>
#include <QDir>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace slew::ui {
namespace {

constexpr char kAgeLimitKey[] = "sky/elementSetAgeLimitDays";

// "1 element set", "2 element sets" (no translator supplies plural forms).
QString count(qsizetype n, const QString &one, const QString &many)
{
    return QStringLiteral("%1 %2").arg(n).arg(n == 1 ? one : many);
}

enum Column { SourceColumn, StateColumn, SetsColumn, AgeColumn, RefusedColumn, FormColumn };

QString describeState(const sky::ElementSetSourceStatus &s)
{
    if (s.fetched)
        return s.error.isEmpty() ? QObject::tr("fetched") : QObject::tr("fetched, but %1").arg(s.error);
    if (s.fromCache)
        return s.error.isEmpty() ? QObject::tr("from the cache") : QObject::tr("from the cache: %1").arg(s.error);
    return s.error.isEmpty() ? QObject::tr("not fetched yet") : s.error;
}

} // namespace

ElementSetsDialog::ElementSetsDialog(sky::ElementSetSources *sources, QWidget *parent)
    : QDialog(parent), m_sources(sources)
{
    setWindowTitle(tr("Element sets"));
    setObjectName(QStringLiteral("elementSetsDialog"));
    resize(820, 480);
    auto *layout = new QVBoxLayout(this);
    auto *about = new QLabel(tr("Sources, one per line: GP queries over HTTP(S), such as CelesTrak's "
                                "(…/gp.php?GROUP=amateur&FORMAT=csv, or FORMAT=json; FORMAT=tle stops at "
                                "catalogue number 99999), or local files (file:///…), in any of the forms: TLE, "
                                "CSV, OMM XML, JSON, OMM KVN. Slew keeps the last good copy of each and works "
                                "from it offline."));
    about->setTextFormat(Qt::PlainText);
    about->setWordWrap(true);
    layout->addWidget(about);
    m_urls = new QPlainTextEdit;
    m_urls->setObjectName(QStringLiteral("elementSetUrls"));
    m_urls->setPlaceholderText(QLatin1String(sky::kExampleElementSetUrl));
    m_urls->setMaximumHeight(110);
    QStringList lines;
    for (const QUrl &url : sources->urls().isEmpty() ? sky::savedElementSetUrls() : sources->urls())
        lines << url.toString();
    m_urls->setPlainText(lines.join(u'\n'));
    layout->addWidget(m_urls);

    auto *form = new QFormLayout;
    m_ageLimit = new QDoubleSpinBox;
    m_ageLimit->setObjectName(QStringLiteral("elementSetAgeLimit"));
    m_ageLimit->setRange(sky::kLeastElementAgeLimitDays, sky::kMostElementAgeLimitDays);
    m_ageLimit->setDecimals(1);
    m_ageLimit->setSuffix(tr(" days"));
    m_ageLimit->setValue(savedAgeLimitDays());
    m_ageLimit->setMaximumWidth(140);
    m_ageLimit->setToolTip(tr("A satellite is tracked, by One target and by the schedule, only while its elements "
                              "are at most this far from their epoch; older sets are named below and on the "
                              "Tracking tab"));
    form->addRow(tr("Track sets up to"), m_ageLimit);
    layout->addLayout(form);

    auto *buttons = new QHBoxLayout;
    m_refresh = new QPushButton(tr("&Refresh now"));
    m_refresh->setObjectName(QStringLiteral("elementSetRefresh"));
    auto *addFile = new QPushButton(tr("Add a &file…"));
    addFile->setObjectName(QStringLiteral("elementSetAddFile"));
    buttons->addWidget(m_refresh);
    buttons->addWidget(addFile);
    buttons->addStretch();
    layout->addLayout(buttons);

    m_message = new QLabel;
    m_message->setObjectName(QStringLiteral("elementSetMessage"));
    m_message->setWordWrap(true);
    layout->addWidget(m_message);

    m_status = new QTreeWidget;
    m_status->setObjectName(QStringLiteral("elementSetStatus"));
    m_status->setHeaderLabels(
        {tr("Source / satellite"), tr("State / epoch"), tr("Sets / number"), tr("Age"), tr("Refused"), tr("Form")});
    m_status->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_status->header()->setSectionResizeMode(SourceColumn, QHeaderView::Stretch);
    layout->addWidget(m_status, 1);

    m_staleWarning = new QLabel;
    m_staleWarning->setObjectName(QStringLiteral("elementSetStaleWarning"));
    m_staleWarning->setWordWrap(true);
    m_staleWarning->setProperty("refused", true); // the theme's warning colour
    layout->addWidget(m_staleWarning);

    auto *close = new QDialogButtonBox(QDialogButtonBox::Close);
    layout->addWidget(close);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_refresh, &QPushButton::clicked, this, &ElementSetsDialog::refresh);
    connect(addFile, &QPushButton::clicked, this, [this] {
        chooseFile(this, FileChoice::Open, tr("Element sets"), QString(), tr("Element sets (*.csv *.xml *.json *.kvn *.txt *.tle *.3le);;All files (*)"),
                   [this](const QString &path) { this->addFile(path); });
    });
    connect(m_ageLimit, &QDoubleSpinBox::valueChanged, this, [this](double days) {
        QSettings().setValue(QLatin1String(kAgeLimitKey), days);
        showStatus();
        emit ageLimitChanged(days);
    });
    connect(m_sources, &sky::ElementSetSources::setsChanged, this, &ElementSetsDialog::showStatus);
    connect(m_sources, &sky::ElementSetSources::loaded, this, [this] {
        m_message->setText(tr("Read: %1 in all.").arg(count(m_sources->sets().size(), tr("element set"), tr("element sets"))));
    });
    connect(m_sources, &sky::ElementSetSources::finished, this, [this] {
        m_refresh->setEnabled(true);
        qsizetype failed = 0;
        for (const sky::ElementSetSourceStatus &s : m_sources->status())
            failed += sky::sourceFailed(s) ? 1 : 0;
        const QString total = count(m_sources->sets().size(), tr("element set"), tr("element sets"));
        m_message->setText(failed == 0 ? tr("Refreshed: %1 in all.").arg(total)
                                       : tr("%1 not refreshed, see below why; %2 in all.")
                                             .arg(count(failed, tr("source"), tr("sources")), total));
    });
    showStatus();
}

double ElementSetsDialog::savedAgeLimitDays()
{
    const std::optional<double> days = input::finiteNumber(QSettings().value(QLatin1String(kAgeLimitKey)).toString());
    // A hand-edited value outside what the dialog allows is not taken.
    return days && *days >= sky::kLeastElementAgeLimitDays && *days <= sky::kMostElementAgeLimitDays
               ? *days
               : sky::kElementAgeLimitDays;
}

bool ElementSetsDialog::readUrls(QList<QUrl> *urls, QString *error) const
{
    const QStringList lines = m_urls->toPlainText().split(u'\n');
    for (int i = 0; i < lines.size(); ++i) {
        const QString line = lines[i].trimmed();
        if (line.isEmpty())
            continue;
        const std::optional<QUrl> url = sky::elementSetUrl(line);
        if (!url) {
            *error = tr("Line %1 is not an http, https or file URL: %2").arg(i + 1).arg(line);
            return false;
        }
        if (!urls->contains(*url))
            urls->append(*url);
    }
    return true;
}

bool ElementSetsDialog::refresh()
{
    QList<QUrl> urls;
    QString error;
    if (!readUrls(&urls, &error)) {
        m_message->setText(error);
        return false;
    }
    if (urls.isEmpty()) {
        m_message->setText(tr("No sources: add a URL or a file first."));
        return false;
    }
    sky::saveElementSetUrls(urls);
    m_sources->setUrls(urls);
    m_refresh->setEnabled(false);
    m_message->setText(tr("Fetching %1…").arg(count(urls.size(), tr("source"), tr("sources"))));
    m_sources->refresh();
    return true;
}

void ElementSetsDialog::addFile(const QString &path)
{
    QString text = m_urls->toPlainText().trimmed();
    if (!text.isEmpty())
        text += u'\n';
    m_urls->setPlainText(text + QUrl::fromLocalFile(path).toString());
    // Its sets at once: the files are read, the downloads stay as cached
    // (no network until Refresh).
    QList<QUrl> urls;
    QString error;
    if (!readUrls(&urls, &error)) {
        m_message->setText(error);
        return;
    }
    sky::saveElementSetUrls(urls);
    m_sources->setUrls(urls);
    m_message->setText(tr("Reading %1…").arg(QDir::toNativeSeparators(path)));
    m_sources->loadFromCache(true);
}

void ElementSetsDialog::showStatus()
{
    m_status->clear();
    for (const sky::ElementSetSourceStatus &s : m_sources->status()) {
        auto *item = new QTreeWidgetItem(m_status);
        item->setText(SourceColumn, s.url.toString());
        item->setText(StateColumn, describeState(s));
        if (s.setCount > 0) {
            item->setText(FormColumn, sky::formName(s.form));
            item->setToolTip(FormColumn, tr("the form the copy held now is written in, told from its content"));
        }
        item->setText(SetsColumn, QString::number(s.setCount));
        item->setText(AgeColumn, describeAgeSince(s.cachedAt));
        item->setText(RefusedColumn, QString::number(s.refusals.size()));
        QStringList refusals;
        for (const sky::ElementSetRefusal &r : s.refusals)
            refusals << tr("%1: %2").arg(r.where(), r.reason);
        item->setToolTip(RefusedColumn, refusals.join(u'\n'));
        item->setToolTip(StateColumn, describeState(s));
        item->setToolTip(AgeColumn, tr("how long ago this copy was downloaded"));
        // Each set under its source, with the age of its elements.
        const double now = sky::julianFromUnixSeconds(QDateTime::currentMSecsSinceEpoch() / 1000.0);
        for (const sky::ElementSet &t : m_sources->setsFrom(m_status->topLevelItemCount() - 1)) {
            auto *child = new QTreeWidgetItem(item);
            child->setText(SourceColumn, t.name.isEmpty() ? tr("(no name)") : t.name);
            const QDateTime epoch = sky::utcFromJulian(t.epochJulian());
            child->setText(StateColumn, epoch.toString(QStringLiteral("yyyy-MM-dd hh:mm 'UTC'")));
            child->setText(SetsColumn, QString::number(t.catalogueNumber));
            child->setText(AgeColumn, tr("%1 days").arg(now - t.epochJulian(), 0, 'f', 1));
            child->setToolTip(AgeColumn, tr("the age of the elements: predictions drift as it grows"));
        }
    }
    m_status->expandAll();
    const QList<sky::ElementSet> sets = m_sources->sets();
    const double now = sky::julianFromUnixSeconds(QDateTime::currentMSecsSinceEpoch() / 1000.0);
    const QList<sky::ElementAge> stale = sky::staleElements(sets, now, m_ageLimit->value());
    if (stale.isEmpty()) {
        m_staleWarning->clear();
        return;
    }
    QStringList named;
    for (qsizetype i = 0; i < stale.size() && i < 5; ++i) {
        const sky::ElementSet &t = *stale[i].set;
        named << tr("%1 (%2 days)")
                     .arg(t.name.isEmpty() ? QString::number(t.catalogueNumber) : t.name)
                     .arg(stale[i].ageDays, 0, 'f', 0);
    }
    m_staleWarning->setText(tr("%1 older than the limit, not tracked until refreshed: %2%3")
                                .arg(count(stale.size(), tr("element set"), tr("element sets")),
                                     named.join(QStringLiteral(", ")), stale.size() > 5 ? tr(", …") : QString()));
}

} // namespace slew::ui
