# Golden values for analysis/stats/posthoc (tests/analysis/stats/test_posthoc.cpp), from R's own
# pairwise.t.test and p.adjust. Run: Rscript make_golden.R  (writes data.csv and golden.csv here).
set.seed(20261202)
subjects <- sprintf("s%02d", 1:9)
group <- rep(c("novice", "musician", "engineer"), each = 3)
method <- c("modal", "bandpass", "recorded")
material <- c("wood", "metal")
d <- expand.grid(material = material, method = method, subject = subjects, rep = 1:2,
                 stringsAsFactors = FALSE)
d$group <- group[match(d$subject, subjects)]
d$score <- round(50 + 8 * (d$method == "recorded") - 5 * (d$method == "bandpass") +
                 3 * (d$material == "metal") + 4 * (d$group == "musician") +
                 rnorm(nrow(d), sd = 6), 2)
d <- d[order(d$subject, d$method, d$material, d$rep), c("subject", "group", "method", "material", "score")]
write.csv(d, "data.csv", row.names = FALSE)

rows <- list()
add <- function(factor, tab, p_raw, method) {
  for (a in rownames(tab)) for (b in colnames(tab)) if (!is.na(tab[a, b]))
    rows[[length(rows) + 1]] <<- data.frame(factor = factor, a = b, b = a, adjust = method,
                                            p_adjusted = tab[a, b], p = p_raw[a, b])
}
# within: the subjects' means per method (averaged over material and repetitions)
w <- aggregate(score ~ subject + method, data = d, FUN = mean)
w$method <- factor(w$method, levels = method)
w <- w[order(w$method, w$subject), ]
raw_w <- pairwise.t.test(w$score, w$method, paired = TRUE, p.adjust.method = "none")$p.value
for (m in c("holm", "bonferroni", "none"))
  add("method", pairwise.t.test(w$score, w$method, paired = TRUE, p.adjust.method = m)$p.value, raw_w, m)
# between: one score per subject (mean over every cell), pooled SD over all groups
b <- aggregate(score ~ subject + group, data = d, FUN = mean)
b$group <- factor(b$group, levels = unique(group))
raw_b <- pairwise.t.test(b$score, b$group, p.adjust.method = "none")$p.value
for (m in c("holm", "bonferroni", "none"))
  add("group", pairwise.t.test(b$score, b$group, p.adjust.method = m)$p.value, raw_b, m)
out <- do.call(rbind, rows)
# the mean differences (a - b) and t statistics, for the paired comparisons
out$mean_diff <- NA; out$t <- NA
for (i in seq_len(nrow(out))) {
  if (out$factor[i] == "method") {
    x <- w$score[w$method == out$a[i]]; y <- w$score[w$method == out$b[i]]
    tt <- t.test(x, y, paired = TRUE)
    out$mean_diff[i] <- mean(x - y); out$t[i] <- unname(tt$statistic)
  } else {
    out$mean_diff[i] <- mean(b$score[b$group == out$a[i]]) - mean(b$score[b$group == out$b[i]])
  }
}
write.csv(out, "golden.csv", row.names = FALSE)
