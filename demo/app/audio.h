/* SPDX-License-Identifier: MIT */
// audio.h - the table's sounds, synthesised in code when the window opens
// (no asset files): the click of two balls, the thud of a cushion, a ball
// dropping into a pocket, the cue's strike.  Volume follows the impulse of
// the contact, the stereo position its place on the table.  With no audio
// device (a server without sound, SDL_AUDIODRIVER=dummy) it stays silent
// and says why once; nothing else changes.
#ifndef C2D_DEMO_AUDIO_H
#define C2D_DEMO_AUDIO_H

#include <SDL.h>

#include <cstddef>
#include <string>
#include <vector>

namespace demo {

enum class Sound { Click, Cushion, Pocket, Strike };

class Audio {
public:
    // open false: silent from the start (no device is opened).
    explicit Audio(bool open = true);
    ~Audio();
    Audio(const Audio &) = delete;
    Audio &operator=(const Audio &) = delete;

    bool available() const { return device_ != 0; }
    const std::string &problem() const { return problem_; }  // why there is no sound
    void toggle_mute();
    bool muted() const { return muted_; }
    // impulse in N s (a strike: the cue ball's momentum); pan -1 (left) .. 1.
    void play(Sound sound, double impulse, double pan);

    // The sound's samples (mono, kRate per second), for tests and plots.
    static std::vector<float> synthesise(Sound sound);
    static constexpr int kRate = 44100;

private:
    struct Voice {
        const std::vector<float> *samples;
        double position, rate;
        float left, right;
    };
    static void callback(void *self, Uint8 *stream, int bytes);
    void mix(float *out, size_t values);  // interleaved stereo

    SDL_AudioDeviceID device_ = 0;
    std::string problem_;
    bool muted_ = false;
    std::vector<float> sounds_[4];
    std::vector<Voice> voices_;  // guarded by SDL_LockAudioDevice
    std::vector<float> buffer_;  // the callback's, sized at its first call
    unsigned variation_ = 12345;  // pitch jitter, so repeats differ
};

}  // namespace demo

#endif
