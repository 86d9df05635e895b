#include "caption_dialog.h"

#include <QDialogButtonBox>
#include <QLabel>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QTabWidget>
#include <QVBoxLayout>

namespace lb {

namespace {

// The languages a lesson is written in: the code the lesson file keys a caption by (data) and
// the name the tab shows (translated where shown, in this dialog's context).
struct Language
{
    const char *code;
    const char *name;
};
constexpr Language kLanguages[] = {{"en", QT_TRANSLATE_NOOP("lb::CaptionDialog", "English")},
                                   {"pt", QT_TRANSLATE_NOOP("lb::CaptionDialog", "Portuguese")},
                                   {"de", QT_TRANSLATE_NOOP("lb::CaptionDialog", "German")}};

} // namespace

CaptionDialog::CaptionDialog(const QMap<QString, QString> &captions, const QString &uiLanguage,
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
    for (const Language &language : kLanguages) {
        const QString code = QString::fromLatin1(language.code);
        auto *field = new QPlainTextEdit(captions.value(code), this);
        field->setObjectName("caption_" + code);
        field->setTabChangesFocus(true);
        m_others.remove(code);
        m_fields.insert(code, field);
        //: a caption's tab: %1 the language's name, %2 its code (en, pt, de)
        const int tab = m_tabs->addTab(field, tr("%1 (%2)").arg(tr(language.name), code));
        if (code == uiLanguage)
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
                                 //: %1 the language's code (en, pt, de); %2, %3 counts
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
