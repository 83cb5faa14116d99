# Golden values for tests/analysis/stats/test_psychophysics.cpp: R's binom.test (exact p and
# Clopper-Pearson interval), and the Macmillan & Creelman d' formulas evaluated with R's
# pnorm/qnorm and inverted with uniroot (an independent numerical inversion).
# Run from this folder: Rscript make_golden.R
g17 <- function(x) sprintf("%.17g", x)
cases <- data.frame(x = c(7, 15, 31, 0, 20, 12, 3, 44, 9),
                    n = c(10, 20, 40, 12, 20, 30, 25, 60, 9),
                    p0 = c(0.5, 0.5, 0.5, 0.5, 0.5, 0.3, 1/3, 0.5, 0.5),
                    alt = c("two.sided", "greater", "two.sided", "two.sided", "greater", "two.sided",
                            "less", "greater", "two.sided"), stringsAsFactors = FALSE)
out <- do.call(rbind, lapply(seq_len(nrow(cases)), function(i) {
  b <- binom.test(cases$x[i], cases$n[i], cases$p0[i], alternative = cases$alt[i])
  data.frame(x = cases$x[i], n = cases$n[i], p0 = g17(cases$p0[i]), alternative = cases$alt[i],
             p = g17(b$p.value), ci_low = g17(b$conf.int[1]), ci_high = g17(b$conf.int[2]))
}))
write.csv(out, "binom_golden.csv", row.names = FALSE, quote = FALSE)

pc_abx <- function(d) pnorm(d / sqrt(2)) * pnorm(d / 2) + pnorm(-d / sqrt(2)) * pnorm(-d / 2)
inv <- function(f, target) uniroot(function(d) f(d) - target, c(0, 20), tol = 1e-14)$root
pcs <- c(0.55, 0.6, 0.7, 0.76, 0.85, 0.95, 0.99)
sdt <- data.frame(pc = pcs, dprime_2afc = g17(sqrt(2) * qnorm(pcs)),
                  dprime_abx = g17(sapply(pcs, function(p) inv(pc_abx, p))))
write.csv(sdt, "dprime_golden.csv", row.names = FALSE, quote = FALSE)

# Same-different, differencing model: k from F, d' from H.
hf <- data.frame(H = c(0.6, 0.75, 0.9, 0.5, 0.95), F = c(0.3, 0.2, 0.1, 0.45, 0.4))
sd_rows <- do.call(rbind, lapply(seq_len(nrow(hf)), function(i) {
  k <- -sqrt(2) * qnorm(hf$F[i] / 2)
  h <- function(d) pnorm((d - k) / sqrt(2)) + pnorm((-d - k) / sqrt(2))
  data.frame(H = hf$H[i], F = hf$F[i], k = g17(k), dprime = g17(inv(h, hf$H[i])))
}))
write.csv(sd_rows, "same_different_golden.csv", row.names = FALSE, quote = FALSE)
