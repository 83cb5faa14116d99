# Golden values for tests/analysis/stats/test_vandendoel2002.cpp: the published tables of van den Doel
# et al. (2002) summarised by R. Table 1: medians of a_v per object and pooled (the paper used
# 16 dB). Table 2: column medians; naive vs energy per object by the paired Wilcoxon signed-rank
# test (exact = NULL as R's default: ties/zeros force the normal approximation with continuity
# correction, so exact = FALSE too, and the uncorrected variant) and the sign test (binom.test) - a
# check of our signed-rank test on numbers with ties and zeros, not an analysis of the paper: the
# columns' ceilings differ (179 vs 100, 128 vs 41 tokens), so a paired test of the counts is confounded.
# Run from this folder: Rscript make_golden.R
g17 <- function(x) sprintf("%.17g", x)
t1 <- read.csv("table1_av.csv", comment.char = "#")
t2 <- read.csv("table2_tokens.csv", comment.char = "#")
med <- data.frame(what = c("vase", "bowl", "pooled", "Vn", "Ve", "Bn", "Be"),
                  median = g17(c(median(t1$av_db[t1$object == "vase"]), median(t1$av_db[t1$object == "bowl"]),
                                 median(t1$av_db), median(t2$Vn), median(t2$Ve), median(t2$Bn), median(t2$Be))))
write.csv(med, "medians_golden.csv", row.names = FALSE, quote = FALSE)
tests <- do.call(rbind, lapply(list(c("vase", "Vn", "Ve"), c("bowl", "Bn", "Be")), function(o) {
  x <- t2[[o[2]]]; y <- t2[[o[3]]]
  w <- suppressWarnings(wilcox.test(x, y, paired = TRUE))
  wn <- suppressWarnings(wilcox.test(x, y, paired = TRUE, exact = FALSE, correct = FALSE))
  d <- x - y
  s <- binom.test(sum(d > 0), sum(d != 0))
  data.frame(object = o[1], V = g17(unname(w$statistic)), p = g17(w$p.value), method = w$method,
             p_uncorrected = g17(wn$p.value), sign_positive = sum(d > 0), sign_n = sum(d != 0),
             sign_p = g17(s$p.value))
}))
write.csv(tests, "table2_tests_golden.csv", row.names = FALSE, quote = FALSE)
print(med); print(tests)

# experiment1_series.csv (written by hand from Table 1, see tests/cli/test_cli_stats.cpp): each
# subject's a_v series falls from 20 dB in 1 dB steps, "same" down to their optimum, then one
# "different". The descending method of limits must give back Table 1 and the pooled median 16 dB -
# a check of how a series is read, not of the paper (the series are made from Table 1):
#   median(c(5,16,15,17,14,18,15,3, 13,19,17,20,20,13,16,19)) == 16
