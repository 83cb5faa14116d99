# Golden values for t-tests on data near the double range (Rscript make_golden.R, R 4.2, Debian 12).
# R itself overflows squaring 1e300, so the same tests are run on the data divided by 1e300: t, df and
# p do not change, mean difference and CI scale by 1e300 (the C++ side compares them relatively).
x <- c(1, 2.5, 3, 4.25)        # times 1e300 in the test data
y <- c(0.5, 1, 1.75, 2)        # times 1e300 in the test data
rows <- list()
for (m in c("welch", "student", "paired")) {
  r <- t.test(x, y, paired = (m == "paired"), var.equal = (m == "student"))
  rows[[m]] <- data.frame(method = m, t = unname(r$statistic), df = unname(r$parameter), p = r$p.value,
                          mean_diff = unname(if (m == "paired") r$estimate else r$estimate[1] - r$estimate[2]) * 1e300,
                          ci_low = r$conf.int[1] * 1e300, ci_high = r$conf.int[2] * 1e300)
}
write.csv(do.call(rbind, rows), "ttest_1e300_golden.csv", row.names = FALSE)
d <- data.frame(subject = rep(1:4, 2), group = rep(c("a", "b"), each = 4),
                v = c(sprintf("%.17g", x * 1e300), sprintf("%.17g", y * 1e300)))
write.csv(d, "ttest_1e300.csv", row.names = FALSE, quote = FALSE)
