# Golden values for ms::wald_difference (tests/analysis/stats/test_confusion.cpp): R's prop.test
# two-sample interval for p1 - p2, with and without the continuity correction.
# Run from this folder: Rscript make_prop_test_golden.R   (writes prop_test_golden.csv)
cases <- rbind(c(36, 71, 57, 108), c(6, 16, 49, 93), c(41, 62, 119, 171), c(13, 86, 28, 94),
               c(85, 116, 90, 183), c(10, 20, 10, 21), c(0, 10, 0, 10), c(10, 10, 0, 10), c(3, 7, 50, 60))
out <- NULL
for (i in seq_len(nrow(cases))) {
  k <- cases[i, ]
  for (correct in c(TRUE, FALSE)) for (level in c(0.95, 0.9)) {
    ci <- suppressWarnings(prop.test(c(k[1], k[3]), c(k[2], k[4]), correct = correct, conf.level = level)$conf.int)
    out <- rbind(out, data.frame(x1 = k[1], n1 = k[2], x2 = k[3], n2 = k[4], correct = correct,
                                 conf_level = level, low = ci[1], high = ci[2]))
  }
}
write.csv(out, "prop_test_golden.csv", row.names = FALSE)
