// A text progress bar for CGAL's `callback` named parameter.
//
// On a terminal it redraws one line in place:   [############            ]  42%  stage name
// When stderr is a file or a pipe (logs, CI) it prints nothing, so logs stay readable.

#ifndef SFE_UTILITIES_PROGRESS_BAR_H
#define SFE_UTILITIES_PROGRESS_BAR_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

#ifdef _WIN32
#include <io.h>
#else
#include <unistd.h>
#endif

namespace sfe_utilities {

/// Callable as `bool(double progress)` with `progress` in [0,1]; always returns `true` (it never
/// cancels). CGAL copies the callback it is given, so all copies share one state: drawing and
/// the current stage are the same whichever copy is called. CGAL's parallel algorithms call the
/// callback from a watcher thread, every few microseconds: calls are serialised by a mutex and
/// the line is only redrawn when what it shows changes.
class Terminal_progress_bar
{
public:
  explicit Terminal_progress_bar(const std::string& stage_name = std::string(), int bar_width = 30)
    : m_state(std::make_shared<State>())
  {
    m_state->stage = stage_name;
    m_state->bar_width = std::max(bar_width, 1);
#ifdef _WIN32
    m_state->enabled = _isatty(_fileno(stderr)) != 0;
#else
    m_state->enabled = isatty(fileno(stderr)) != 0;
#endif
  }

  bool operator()(double progress) const
  {
    std::lock_guard<std::mutex> lock(m_state->mutex);
    if(!m_state->enabled)
      return true;
    if(!(progress >= 0)) // also catches NaN
      progress = 0;
    progress = std::min(progress, 1.);
    if(m_state->finished) {
      if(progress >= 1) // repeated completion signal
        return true;
      // Some algorithms make several passes, each from 0 to 1: one line per pass.
      m_state->finished = false;
      m_state->drawn_filled = -1;
      m_state->drawn_percent = -1;
    }
    const int filled = static_cast<int>(std::floor(progress * m_state->bar_width));
    const int percent = static_cast<int>(std::floor(progress * 100));
    if(filled != m_state->drawn_filled || percent != m_state->drawn_percent) {
      m_state->drawn_filled = filled;
      m_state->drawn_percent = percent;
      draw();
    }
    if(progress >= 1)
      end_line();
    return true;
  }

  /// starts a new line for the next stage (the bar restarts at 0%).
  void set_stage(const std::string& stage_name) const
  {
    std::lock_guard<std::mutex> lock(m_state->mutex);
    if(m_state->enabled && !m_state->finished && m_state->drawn_percent >= 0)
      end_line();
    m_state->stage = stage_name;
    m_state->finished = false;
    m_state->drawn_filled = -1;
    m_state->drawn_percent = -1;
  }

  /// ends the current line if a bar is drawn and not complete (e.g. before printing a result).
  void finish() const
  {
    std::lock_guard<std::mutex> lock(m_state->mutex);
    if(m_state->enabled && !m_state->finished && m_state->drawn_percent >= 0)
      end_line();
  }

  /// `true` if stderr is a terminal, i.e. if the bar is drawn at all.
  bool is_enabled() const { return m_state->enabled; }

private:
  struct State
  {
    std::mutex mutex;
    std::string stage;
    int bar_width = 30;
    bool enabled = false;
    bool finished = false;
    int drawn_filled = -1; // what the line currently shows; -1: nothing drawn yet
    int drawn_percent = -1;
  };

  void draw() const
  {
    const std::string bar = std::string(static_cast<std::size_t>(m_state->drawn_filled), '#') +
                            std::string(static_cast<std::size_t>(m_state->bar_width - m_state->drawn_filled), ' ');
    // The trailing "erase to end of line" escape removes leftovers of a longer previous line.
    std::fprintf(stderr, "\r[%s] %3d%%  %s\x1b[K", bar.c_str(), m_state->drawn_percent, m_state->stage.c_str());
    std::fflush(stderr);
  }

  void end_line() const
  {
    std::fputc('\n', stderr);
    std::fflush(stderr);
    m_state->finished = true;
  }

  std::shared_ptr<State> m_state;
};

} // namespace sfe_utilities

#endif // SFE_UTILITIES_PROGRESS_BAR_H
