/* SPDX-License-Identifier: MIT */
// audio.cpp - see audio.h.  Each sound is a sum of exponentially decaying
// partials a e^(-t/tau) sin(2 pi f t) plus filtered noise bursts (a
// one-pole low-pass, y += k (x - y)), the way struck hard objects ring:
//   click    phenolic on phenolic: partials at 2.2-6.3 kHz, tau 4-9 ms
//   cushion  rubber and wood: 95-210 Hz, tau 25-45 ms, a dull low-passed thump
//   pocket   a knock on the pocket's edge, two rattles, the roll away
//   strike   leather tip on the cue ball: 0.9-2 kHz, tau 5-8 ms
// Gain is (impulse / reference)^0.6, clamped to 1; voices are mixed in
// floats and soft-limited above 0.5 (never reaching 1).
#include "app/audio.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace demo {

namespace {

struct Partial {
    double freq, tau, amp;
};

class Noise {
public:
    float next() {
        state_ = state_ * 1664525u + 1013904223u;
        return static_cast<float>(state_ >> 8) / 8388608.0f - 1.0f;
    }

private:
    unsigned state_ = 22222u;
};

void add_partials(std::vector<float> &out, double start, const std::vector<Partial> &partials) {
    const size_t first = static_cast<size_t>(start * Audio::kRate);
    for (size_t i = first; i < out.size(); ++i) {
        const double t = static_cast<double>(i - first) / Audio::kRate;
        const double attack = std::min(1.0, t / 0.0004);
        double v = 0;
        for (const Partial &p : partials) v += p.amp * std::exp(-t / p.tau) * std::sin(2 * M_PI * p.freq * t);
        out[i] += static_cast<float>(attack * v);
    }
}

// Noise through a one-pole low-pass of coefficient k (1: none), decaying.
void add_noise(std::vector<float> &out, double start, double tau, double amp, float k, Noise &noise) {
    const size_t first = static_cast<size_t>(start * Audio::kRate);
    float y = 0;
    for (size_t i = first; i < out.size(); ++i) {
        const double t = static_cast<double>(i - first) / Audio::kRate;
        y += k * (noise.next() - y);
        out[i] += static_cast<float>(amp * std::exp(-t / tau)) * y;
    }
}

// Whether asking SDL for sound is worth it.  With no sound server and no
// ALSA card, SDL's last resort (ALSA) prints a screenful of libasound errors
// before failing; so without SDL_AUDIODRIVER, a PulseAudio/PipeWire socket
// or a card in /proc/asound/cards, the window stays silent without asking.
bool sound_device_likely(std::string &why) {
    const auto set = [](const char *name) {
        const char *v = std::getenv(name);
        return v && *v;
    };
    if (set("SDL_AUDIODRIVER") || set("PULSE_SERVER")) return true;
    const char *runtime = std::getenv("XDG_RUNTIME_DIR");
    if (runtime && *runtime) {
        std::error_code ignored;
        for (const char *socket : {"/pulse/native", "/pipewire-0"})
            if (std::filesystem::exists(std::string(runtime) + socket, ignored)) return true;
    }
    FILE *cards = std::fopen("/proc/asound/cards", "r");
    if (!cards) {
        std::error_code ignored;
        if (!std::filesystem::exists("/proc/self", ignored)) return true;  // not Linux: let SDL look
        why = "no sound server and no sound card";                        // Linux without ALSA
        return false;
    }
    char line[128] = "";
    const bool none = !std::fgets(line, sizeof line, cards) || std::strstr(line, "no soundcards");
    std::fclose(cards);
    if (none) why = "no sound server and no sound card";
    return !none;
}

double reference_impulse(Sound s) {
    switch (s) {
    case Sound::Click: return 0.6;     // 0.17 kg, ~3.5 m/s change
    case Sound::Cushion: return 0.9;
    case Sound::Pocket: return 0.35;
    case Sound::Strike: return 1.6;
    }
    return 1;
}

}  // namespace

std::vector<float> Audio::synthesise(Sound sound) {
    Noise noise;
    std::vector<float> out;
    switch (sound) {
    case Sound::Click:
        out.assign(kRate * 70 / 1000, 0.0f);
        add_partials(out, 0, {{2250, 0.009, 0.35}, {3830, 0.006, 0.3}, {6300, 0.004, 0.2}, {1400, 0.012, 0.1}});
        add_noise(out, 0, 0.0015, 0.5, 0.8f, noise);
        break;
    case Sound::Cushion:
        out.assign(kRate * 180 / 1000, 0.0f);
        add_partials(out, 0, {{95, 0.045, 0.55}, {150, 0.03, 0.35}, {210, 0.025, 0.2}});
        add_noise(out, 0, 0.012, 0.6, 0.08f, noise);
        add_partials(out, 0, {{1800, 0.003, 0.06}});
        break;
    case Sound::Pocket:
        out.assign(kRate * 600 / 1000, 0.0f);
        add_partials(out, 0, {{180, 0.035, 0.5}, {320, 0.02, 0.3}, {2400, 0.004, 0.12}});
        add_noise(out, 0, 0.01, 0.4, 0.2f, noise);
        add_partials(out, 0.075, {{2600, 0.004, 0.15}, {410, 0.015, 0.2}});
        add_partials(out, 0.13, {{2900, 0.003, 0.08}, {360, 0.012, 0.12}});
        add_noise(out, 0.16, 0.16, 0.25, 0.03f, noise);  // the roll along the return
        break;
    case Sound::Strike:
        out.assign(kRate * 60 / 1000, 0.0f);
        add_partials(out, 0, {{920, 0.008, 0.35}, {1480, 0.006, 0.25}, {2050, 0.005, 0.12}});
        add_noise(out, 0, 0.002, 0.35, 0.35f, noise);
        break;
    }
    // fade the last 5 ms so no sound ends in a click of its own
    const size_t fade = std::min(out.size(), static_cast<size_t>(kRate / 200));
    for (size_t i = 0; i < fade; ++i) out[out.size() - 1 - i] *= static_cast<float>(i) / static_cast<float>(fade);
    return out;
}

Audio::Audio(bool open) {
    if (!open) {
        problem_ = "sound off";
        return;
    }
    for (int s = 0; s < 4; ++s) sounds_[s] = synthesise(static_cast<Sound>(s));
    if (!sound_device_likely(problem_)) return;
    if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0) {
        problem_ = SDL_GetError();
        return;
    }
    SDL_AudioSpec want{}, have{};
    want.freq = kRate;
    want.format = AUDIO_F32SYS;
    want.channels = 2;
    want.samples = 512;
    want.callback = &Audio::callback;
    want.userdata = this;
    device_ = SDL_OpenAudioDevice(nullptr, 0, &want, &have, 0);
    if (device_ == 0) {
        problem_ = SDL_GetError();
        SDL_QuitSubSystem(SDL_INIT_AUDIO);
        return;
    }
    voices_.reserve(32);
    buffer_.resize(static_cast<size_t>(have.samples) * have.channels);
    SDL_PauseAudioDevice(device_, 0);
}

Audio::~Audio() {
    if (device_ == 0) return;
    SDL_CloseAudioDevice(device_);
    SDL_QuitSubSystem(SDL_INIT_AUDIO);
}

void Audio::toggle_mute() {
    muted_ = !muted_;
    if (device_ == 0 || !muted_) return;
    SDL_LockAudioDevice(device_);
    voices_.clear();
    SDL_UnlockAudioDevice(device_);
}

void Audio::play(Sound sound, double impulse, double pan) {
    if (device_ == 0 || muted_ || !(impulse > 0)) return;
    const double gain = 0.7 * std::pow(std::min(1.0, impulse / reference_impulse(sound)), 0.6);
    if (gain < 0.015) return;
    variation_ = variation_ * 1103515245u + 12345u;
    const double rate = 0.94 + 0.12 * static_cast<double>((variation_ >> 16) & 0x7fff) / 32767.0;
    const double p = std::clamp(pan, -1.0, 1.0) * 0.6;
    const Voice v{&sounds_[static_cast<int>(sound)], 0.0, rate, static_cast<float>(gain * std::sqrt((1 - p) / 2)),
                  static_cast<float>(gain * std::sqrt((1 + p) / 2))};
    SDL_LockAudioDevice(device_);
    if (voices_.size() >= 32) {  // drop the quietest
        auto quietest = std::min_element(voices_.begin(), voices_.end(),
                                         [](const Voice &a, const Voice &b) { return a.left + a.right < b.left + b.right; });
        *quietest = v;
    } else {
        voices_.push_back(v);
    }
    SDL_UnlockAudioDevice(device_);
}

void Audio::callback(void *self, Uint8 *stream, int bytes) {
    Audio &audio = *static_cast<Audio *>(self);
    const size_t values = static_cast<size_t>(std::max(0, bytes)) / sizeof(float);
    if (audio.buffer_.size() < values) audio.buffer_.resize(values);  // once: the device's buffer size
    audio.mix(audio.buffer_.data(), values);
    std::memcpy(stream, audio.buffer_.data(), values * sizeof(float));
}

void Audio::mix(float *out, size_t values) {
    std::fill(out, out + values, 0.0f);
    for (Voice &v : voices_) {
        const std::vector<float> &s = *v.samples;
        for (size_t f = 0; f < values; f += 2) {
            const size_t i = static_cast<size_t>(v.position);
            if (i + 1 >= s.size()) {
                v.position = static_cast<double>(s.size());
                break;
            }
            const float frac = static_cast<float>(v.position - static_cast<double>(i));
            const float x = s[i] + (s[i + 1] - s[i]) * frac;
            out[f] += x * v.left;
            out[f + 1] += x * v.right;
            v.position += v.rate;
        }
    }
    voices_.erase(std::remove_if(voices_.begin(), voices_.end(),
                                 [](const Voice &v) { return v.position + 1 >= static_cast<double>(v.samples->size()); }),
                  voices_.end());
    for (size_t i = 0; i < values; ++i) {
        const float x = out[i], a = std::fabs(x);
        if (a > 0.5f) out[i] = std::copysign(0.5f + (a - 0.5f) / (1 + 2 * (a - 0.5f)), x);  // soft limit below 1
    }
}

}  // namespace demo
