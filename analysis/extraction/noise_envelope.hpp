// Time-varying noise of a recording: a room tail (broadband noise that decays after the strike) on
// top of the stationary floor, as a white-equivalent variance per block of samples. Per frame of a
// short-time spectrogram, a low quantile of the periodogram across frequency measures it (the modes
// occupy few bins; the 20th percentile of an exponential variable is -ln 0.8 of its mean); the
// estimates are made non-increasing (a tail does not grow back) and kept only where they stand
// clearly above the floor, so stationary noise changes nothing.
// Why: against the floor of the recording's last quarter, a room tail looks like hundreds of modes
// (it decays, so ESPRIT and the pursuit fit it with damped sinusoids); weighed against its own level
// it does not.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/extraction/damped_fit.hpp"

namespace ms {

struct NoiseEnvelope {
  std::size_t block = 0;          // samples per block
  std::vector<double> variance;   // white-equivalent variance per block from the analysis start
  double floor_variance = 0.0;    // after the last block, and where nothing stands out
  bool flat() const { return variance.empty(); }
  double at(std::size_t sample) const {
    const std::size_t k = block ? sample / block : 0;
    return k < variance.size() ? variance[k] : floor_variance;
  }
  // What the component is worth in the recording: the weighted least-squares fit of its pole to
  // residual + component (weights 1/variance) and the residual reduction it gives, in noise
  // variances. Unlike its energy over the floor this does not credit a component fitted to loud
  // decaying noise with the energy its decay carries into quiet later samples it does not explain.
  double weighted_fit_gain(const std::vector<double>& residual, const DampedComponent& c) const;
  // weighted_fit_gain of each component against the same residual, eight components per pass over
  // the samples (a room recording's fit judges a hundred or more at a time).
  std::vector<double> weighted_fit_gains(const std::vector<double>& residual,
                                         const std::vector<DampedComponent>& components) const;
  // The white-noise variance with which an unweighted least-squares fit of a mode decaying by
  // decay_per_sample (amplitude), over n < frames, estimates a parameter whose sensitivity grows as
  // n^power (0: the amplitude; 2: frequency and decay, whose derivatives carry a factor n): the
  // envelope averaged with weights n^power e^{-2 d n}. The floor when flat. A slow mode's amplitude
  // is fixed by its first samples, where the tail is loud; its frequency by later ones.
  double variance_seen(double decay_per_sample, std::size_t frames, int power) const;
};

// x: the analysed signal (its first sample is the time origin, e.g. the onset); floor_variance: the
// stationary white-noise variance. Frames of ~23 ms (hop half that), blocks of 1/16 frame.
NoiseEnvelope estimate_noise_envelope(const std::vector<double>& x, double sample_rate_hz, double floor_variance);

// Energy of Re(b e^{s n}) over n in [from, to) (closed form).
double component_energy(const DampedComponent& c, std::size_t from, std::size_t to);

}  // namespace ms
