#pragma once
// When detections are hidden: from `first_s` on, every `period_s`, a blackout of `frames`
// frames (counted as they arrive, so a dropped frame does not stretch the blackout).
namespace kestrel::scenario {

class BlackoutSchedule {
 public:
  BlackoutSchedule(int frames, double first_s, double period_s);

  /// Called once per frame in capture order: true if the frame captured at `t_s` is hidden.
  bool hide(double t_s);

 private:
  int frames_;
  double first_, period_;
  long current_ = -1;  // index of the blackout period we are in
  int hidden_in_current_ = 0;
};

}  // namespace kestrel::scenario
