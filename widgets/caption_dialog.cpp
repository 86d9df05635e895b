#include "caption_dialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QTabWidget>
#include <QVBoxLayout>

namespace lb {

namespace {

// The languages a lesson is written in, with their names for the tabs.
QList<QPair<QString, QString>> languages()
{
    return {{"en", QObject::tr("English")},
            {"pt", QObject::tr("Portuguese")},
            {"de", QObject::tr("German")}};
}

} // namespace

CaptionDialog::CaptionDialog(const QMap<QString, QString> &captions, const QString &language,
                             int maxCharacters, QWidget *parent)
    : QDialog(parent), m_others(captions), m_max(maxCharacters)
{
    setObjectName("captionDialog");
    setWindowTitle(tr("Edit Caption"));
    auto *layout = new QVBoxLayout(this);
    auto *intro = new QLabel(tr("What the class reads under the view. Markdown: *italic*, "
                                "**bold**, `code`, lists. An empty language shows English."),
                             this);
    intro->setWordWrap(true);
    layout->addWidget(intro);
    m_tabs = new QTabWidget(this);
    for (const auto &[code, name] : languages()) {
        auto *field = new QPlainTextEdit(captions.value(code), this);
        field->setObjectName("caption_" + code);
        field->setTabChangesFocus(true);
        m_others.remove(code);
        m_fields.insert(code, field);
        const int tab = m_tabs->addTab(field, QString("%1 (%2)").arg(name, code));
        if (code == language)
            m_tabs->setCurrentIndex(tab);
    }
    layout->addWidget(m_tabs, 1);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &CaptionDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
    resize(fontMetrics().averageCharWidth() * 70, fontMetrics().height() * 16);
}

QMap<QString, QString> CaptionDialog::captions() const
{
    QMap<QString, QString> result = m_others;
    for (auto it = m_fields.begin(); it != m_fields.end(); ++it)
        if (const QString text = it.value()->toPlainText().trimmed(); !text.isEmpty())
            result.insert(it.key(), text);
    return result;
}

void CaptionDialog::accept()
{
    for (auto it = m_fields.begin(); it != m_fields.end(); ++it) {
        const int length = int(it.value()->toPlainText().trimmed().size());
        if (length > m_max) {
            m_tabs->setCurrentWidget(it.value());
            QMessageBox::warning(this, tr("Edit Caption"),
                                 tr("The %1 caption has %2 characters; a caption holds at most "
                                    "%3. Nothing was changed yet: shorten it, or Cancel.")
                                     .arg(it.key())
                                     .arg(length)
                                     .arg(m_max));
            return;
        }
    }
    QDialog::accept();
}

} // namespace lb
