#!/usr/bin/python3
# Golden values for tests/analysis/estimation/test_perceptual_metric.cpp (Debian python3-scipy 1.10):
# the Bark-band power image of a fixed three-mode test signal from scipy.signal.spectrogram, and its
# loudness in sone through the ISO 226:2003 formulas. Run: /usr/bin/python3 make_golden.py
import csv
import math

import numpy as np
from scipy import signal

FS = 44100.0
N = 1024          # 23 ms rounded up to a power of two at 44.1 kHz
HOP = N // 2
BAND_BARK = 1.0
FULL_SCALE_DB_SPL = 90.0  # a full-scale sine (mean square 1/2) at 90 dB SPL

# The test signal (the C++ test builds the same samples): three damped sinusoids, 0.3 s, as float32.
t = np.arange(int(0.3 * FS)) / FS
x = (0.5 * np.exp(-3.0 * t) * np.sin(2 * np.pi * 440.0 * t)
     + 0.2 * np.exp(-30.0 * t) * np.sin(2 * np.pi * 2500.0 * t + 0.3)
     + 0.05 * np.exp(-100.0 * t) * np.sin(2 * np.pi * 7100.0 * t)).astype(np.float32).astype(np.float64)

# Periodic Hann, no detrending, no padding: frames wholly inside the signal. 'density' scaling is
# |X|^2 / (fs sum w^2), doubled except at 0 Hz and Nyquist, so sum(Sxx) * fs / N is the mean square.
f, _, sxx = signal.spectrogram(x, fs=FS, window='hann', nperseg=N, noverlap=N - HOP, detrend=False,
                               scaling='density', mode='psd')
bark = 6.0 * np.arcsinh(f / 600.0)
bands = int(6.0 * math.asinh(FS / 2 / 600.0) / BAND_BARK) + 1
band_of = np.minimum(bands - 1, np.floor(bark / BAND_BARK).astype(int))
power = np.zeros((sxx.shape[1], bands))
for k in range(1, len(f)):  # the 0 Hz bin is left out
    power[:, band_of[k]] += sxx[k, :] * FS / N

# ISO 226:2003 Table 1 and Eq. (2), linear in log frequency between rows; phon -> sone.
F = [20, 25, 31.5, 40, 50, 63, 80, 100, 125, 160, 200, 250, 315, 400, 500, 630, 800, 1000, 1250, 1600,
     2000, 2500, 3150, 4000, 5000, 6300, 8000, 10000, 12500]
AF = [0.532, 0.506, 0.480, 0.455, 0.432, 0.409, 0.387, 0.367, 0.349, 0.330, 0.315, 0.301, 0.288, 0.276,
      0.267, 0.259, 0.253, 0.250, 0.246, 0.244, 0.243, 0.243, 0.243, 0.242, 0.242, 0.245, 0.254, 0.271, 0.301]
LU = [-31.6, -27.2, -23.0, -19.1, -15.9, -13.0, -10.3, -8.1, -6.2, -4.5, -3.1, -2.0, -1.1, -0.4, 0.0, 0.3,
      0.5, 0.0, -2.7, -4.1, -1.0, 1.7, 2.5, 1.2, -2.1, -7.1, -11.2, -10.7, -3.1]
TF = [78.5, 68.7, 59.5, 51.1, 44.0, 37.5, 31.5, 26.5, 22.1, 17.9, 14.4, 11.4, 8.6, 6.2, 4.4, 3.0, 2.2, 2.4,
      3.5, 1.7, -1.3, -4.2, -6.0, -5.4, -1.5, 6.0, 12.6, 13.9, 12.3]
lf = np.log(F)


def params(freq):
    g = np.log(min(max(freq, F[0]), F[-1]))
    return (np.interp(g, lf, AF), np.interp(g, lf, LU), np.interp(g, lf, TF))


def sone(mean_square, freq):
    if mean_square <= 0:
        return 0.0
    a, lu, tf = params(freq)
    lp = FULL_SCALE_DB_SPL - 10 * math.log10(0.5) + 10 * math.log10(mean_square)
    bf = (0.4 * 10 ** ((lp + lu) / 10 - 9)) ** a - (0.4 * 10 ** ((tf + lu) / 10 - 9)) ** a + 0.005135
    if bf <= 0:
        return 0.0
    ln = 40 * math.log10(bf) + 94
    if ln <= 0:
        return 0.0
    return 2 ** ((ln - 40) / 10) if ln >= 40 else (ln / 40) ** 2.642


with open('bark_power_image.csv', 'w', newline='') as out:
    w = csv.writer(out)
    w.writerow(['frame', 'band', 'mean_square', 'sone'])
    for m in range(power.shape[0]):
        for b in range(bands):
            centre = 600.0 * math.sinh((b + 0.5) * BAND_BARK / 6.0)
            w.writerow([m, b, '%.12g' % power[m, b], '%.12g' % sone(power[m, b], centre)])
