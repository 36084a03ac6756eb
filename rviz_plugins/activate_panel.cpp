#include "rviz_plugins/activate_panel.h"

#include <std_msgs/Empty.h>

#include <QLabel>
#include <QPushButton>
#include <QTime>
#include <QVBoxLayout>
#include <pluginlib/class_list_macros.hpp>

namespace kinematic_coverage::rviz_plugins {

ActivatePanel::ActivatePanel(QWidget* parent)
    : rviz::Panel(parent),
      publisher_(node_.advertise<std_msgs::Empty>("activate", 1)),
      status_label_(new QLabel("Set the start and the goal, then activate.")) {
  auto* button = new QPushButton("&Activate");
  button->setToolTip(
      QString("Publish std_msgs/Empty on %1 (Alt+A): coverage_planner plans a coverage path "
              "with the current polygon, start and goal.")
          .arg(QString::fromStdString(publisher_.getTopic())));
  status_label_->setWordWrap(true);
  auto* layout = new QVBoxLayout;
  layout->addWidget(button);
  layout->addWidget(status_label_);
  layout->addStretch();
  setLayout(layout);
  connect(button, &QPushButton::clicked, this, &ActivatePanel::sendActivate);
}

void ActivatePanel::sendActivate() {
  publisher_.publish(std_msgs::Empty());
  const QString time = QTime::currentTime().toString("HH:mm:ss");
  const QString topic = QString::fromStdString(publisher_.getTopic());
  if (publisher_.getNumSubscribers() == 0) {
    status_label_->setText(
        QString("Activated at %1, but nothing subscribes to %2: is coverage_planner running?")
            .arg(time, topic));
  } else {
    status_label_->setText(QString("Activated at %1 on %2.").arg(time, topic));
  }
}

}  // namespace kinematic_coverage::rviz_plugins

PLUGINLIB_EXPORT_CLASS(kinematic_coverage::rviz_plugins::ActivatePanel, rviz::Panel)
