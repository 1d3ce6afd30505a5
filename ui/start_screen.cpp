#include "ui/start_screen.h"

#include <QComboBox>
#include <QEvent>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace trilho {
namespace ui {

StartScreen::StartScreen(QWidget* parent) : QDialog(parent) {
    setObjectName(QStringLiteral("startScreen"));
    setAutoFillBackground(true);
    auto* outer = new QVBoxLayout(this);
    auto* panel = new QFrame(this);
    panel->setObjectName(QStringLiteral("vbPanel"));
    panel->setFrameShape(QFrame::Panel);
    panel->setFrameShadow(QFrame::Raised);
    panel->setAutoFillBackground(true);
    QPalette pal = panel->palette();
    pal.setColor(QPalette::Window, QColor(192, 192, 192));
    panel->setPalette(pal);
    panel->setMinimumSize(385, 273);  // 5775 x 4095 twips
    auto* v = new QVBoxLayout(panel);
    QFont bold = font();
    bold.setBold(true);
    bold.setPointSize(12);
    university_ = new QLabel(panel);
    school_ = new QLabel(panel);
    title_ = new QLabel(panel);
    for (QLabel* l : {university_, school_, title_}) {
        l->setFont(bold);
        l->setAlignment(Qt::AlignCenter);
        l->setWordWrap(true);
        v->addWidget(l);
    }
    QFont arial = bold;
    arial.setFamily(QStringLiteral("Arial"));
    title_->setFont(arial);
    auto* box = new QFrame(panel);
    box->setFrameShape(QFrame::Box);
    auto* boxLayout = new QVBoxLayout(box);
    authors_ = new QLabel(box);
    authors_->setAlignment(Qt::AlignCenter);
    boxLayout->addWidget(authors_);
    v->addWidget(box);
    credit_ = new QLabel(panel);
    credit_->setAlignment(Qt::AlignCenter);
    credit_->setWordWrap(true);
    v->addWidget(credit_);
    machineLabel_ = new QLabel(panel);
    machine_ = new QComboBox(panel);
    machine_->setObjectName(QStringLiteral("startMachine"));
    for (int i = 0; i < 3; ++i)
        machine_->addItem(QString(), i);
    machineLabel_->setBuddy(machine_);
    auto* machineRow = new QHBoxLayout;
    machineRow->addWidget(machineLabel_);
    machineRow->addWidget(machine_, 1);
    v->addLayout(machineRow);
    ok_ = new QPushButton(panel);
    ok_->setDefault(true);
    ok_->setMinimumSize(81, 33);  // 1215 x 495 twips
    v->addWidget(ok_, 0, Qt::AlignHCenter);
    outer->addStretch();
    outer->addWidget(panel, 0, Qt::AlignCenter);
    outer->addStretch();
    connect(ok_, &QPushButton::clicked, this, &QDialog::accept);
    retranslate();
}

void StartScreen::retranslate() {
    setWindowTitle(tr("Didactic D.N.C. system for the automatic rail"));
    university_->setText(tr("University of São Paulo"));
    school_->setText(tr("Polytechnic School"));
    title_->setText(tr("Numerical Control for the robot's rail"));
    authors_->setText(QStringLiteral("Jerri Regis Biscuola\nVinícius Arouche de Toledo"));
    credit_->setText(tr("Original design, 1996. Rebuilt and finished as trilho."));
    ok_->setText(tr("OK"));
    machineLabel_->setText(tr("&Machine:"));
    machine_->setItemText(0, tr("Robot rail (1996)"));
    machine_->setItemText(1, tr("DC-motor XY table"));
    machine_->setItemText(2, tr("Stepper XY plotter"));
}

void StartScreen::setMachine(MachineKind kind) {
    machine_->setCurrentIndex(static_cast<int>(kind));
}

MachineKind StartScreen::machine() const {
    switch (machine_->currentIndex()) {
        case 1:
            return MachineKind::DcTable;
        case 2:
            return MachineKind::Plotter;
        default:
            return MachineKind::Rail;
    }
}

void StartScreen::changeEvent(QEvent* e) {
    if (e->type() == QEvent::LanguageChange) retranslate();
    QDialog::changeEvent(e);
}

}  // namespace ui
}  // namespace trilho
