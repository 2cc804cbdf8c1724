// SPDX-License-Identifier: GPL-3.0-or-later
#include "radio/radiotransponderdialog.h"

#include "operatortheme.h"
#include "widgets/filechooser.h"

#include "radio/transpondersources.h"

#include <QDialogButtonBox>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>

namespace slew::ui {

RadioTransponderDialog::RadioTransponderDialog(radio::TransponderSources *sources, QWidget *parent)
    : QDialog(parent), m_sources(sources)
{
    setObjectName(QStringLiteral("radioTransponderDialog"));
    setWindowTitle(tr("Transponder sources"));
    m_list = new QListWidget;
    m_list->setObjectName(QStringLiteral("radioTransponderSourceList"));
    m_list->setWordWrap(true);
    m_field = new QLineEdit;
    m_field->setObjectName(QStringLiteral("radioTransponderSourceField"));
    m_field->setPlaceholderText(tr("a .trsp or .json file, or an https:// URL"));
    auto *browse = new QPushButton(tr("Browse…"));
    browse->setObjectName(QStringLiteral("radioBrowseTransponderSource"));
    browse->setAutoDefault(false);
    auto *add = new QPushButton(tr("Add"));
    add->setObjectName(QStringLiteral("radioAddTransponderSource"));
    add->setAutoDefault(false);
    m_remove = new QPushButton(tr("Remove"));
    m_remove->setObjectName(QStringLiteral("radioRemoveTransponderSource"));
    m_remove->setAutoDefault(false);
    m_refusal = new QLabel;
    m_refusal->setObjectName(QStringLiteral("radioTransponderSourceRefusal"));
    m_refusal->setWordWrap(true);
    m_refusal->setStyleSheet(refusedText());
    m_refusal->hide();
    auto *close = new QDialogButtonBox(QDialogButtonBox::Close);
    connect(close, &QDialogButtonBox::rejected, this, &QDialog::close);

    auto *grid = new QGridLayout(this);
    grid->addWidget(m_list, 0, 0, 1, 3);
    grid->addWidget(m_remove, 1, 2);
    grid->addWidget(m_field, 2, 0);
    grid->addWidget(browse, 2, 1);
    grid->addWidget(add, 2, 2);
    grid->addWidget(m_refusal, 3, 0, 1, 3);
    grid->addWidget(close, 4, 0, 1, 3);
    grid->setColumnStretch(0, 1);

    connect(add, &QPushButton::clicked, this, &RadioTransponderDialog::addSource);
    connect(m_field, &QLineEdit::returnPressed, this, &RadioTransponderDialog::addSource);
    connect(m_remove, &QPushButton::clicked, this, &RadioTransponderDialog::removeSource);
    connect(m_list, &QListWidget::currentRowChanged, this, [this](int row) { m_remove->setEnabled(row >= 0); });
    connect(browse, &QPushButton::clicked, this, [this] {
        chooseFile(this, FileChoice::Open, tr("A transponder file"), QString(),
                   tr("Transponders (*.trsp *.json);;All files (*)"), [this](const QString &path) {
                       m_field->setText(path);
                       addSource();
                   });
    });
    // The list as it stands, another Slew's changes and a refresh's results included.
    connect(m_sources, &radio::TransponderSources::transpondersChanged, this, &RadioTransponderDialog::showSources);
    showSources();
    resize(640, 320);
}

void RadioTransponderDialog::showSources()
{
    const QList<radio::TransponderSourceStatus> status = m_sources->status();
    const QList<QUrl> urls = m_sources->urls();
    const int row = m_list->currentRow();
    m_list->clear();
    for (qsizetype i = 0; i < urls.size(); ++i) {
        // What each gave last, when it has been read; else its name alone.
        const bool read = i < status.size() && (status[i].fetched || status[i].fromCache || !status[i].error.isEmpty());
        m_list->addItem(read ? radio::describeTransponderSource(status[i]) : urls[i].toString());
    }
    m_list->setCurrentRow(std::min(row, int(m_list->count()) - 1));
    m_remove->setEnabled(m_list->currentRow() >= 0);
}

void RadioTransponderDialog::keep(const QList<QUrl> &urls)
{
    // The settings first: that is the list `slew --update-transponders` and
    // the next start read.
    radio::saveTransponderUrls(urls);
    m_sources->setUrls(urls);
}

bool RadioTransponderDialog::addSource()
{
    QString why;
    const std::optional<QUrl> url = radio::transponderSourceUrl(m_field->text(), &why);
    if (url && m_sources->urls().contains(*url))
        why = tr("'%1' is a source already").arg(url->isLocalFile() ? url->toLocalFile() : url->toString());
    if (!url || !why.isEmpty()) {
        m_refusal->setText(why);
        m_refusal->show();
        return false;
    }
    m_refusal->hide();
    m_field->clear();
    keep(m_sources->urls() << *url);
    emit message(tr("transponders: %1 added; fetching every source").arg(url->toString()));
    m_sources->refresh(); // the new one has no copy yet: it is fetched now, the others with it
    showSources();
    m_list->setCurrentRow(m_list->count() - 1);
    return true;
}

void RadioTransponderDialog::removeSource()
{
    const int row = m_list->currentRow();
    QList<QUrl> urls = m_sources->urls();
    if (row < 0 || row >= urls.size())
        return;
    const QUrl gone = urls.takeAt(row);
    keep(urls);
    emit message(tr("transponders: %1 removed").arg(gone.toString()));
    m_sources->loadFromCache(); // the others, as they were
    showSources();
}

} // namespace slew::ui
