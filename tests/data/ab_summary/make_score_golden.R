# Golden values for `modalstudy stats ab --task preference --score` (tests/cli/test_cli_stats_ab_score.cpp):
# per group n, mean, sd and R's one-sample t.test against 0 (95 %), on the rows as they are and on
# each participant's mean per group (aggregate, as afex averages repeated observations). A group whose
# scores are all equal, or that has one score, has no t-test (t.test stops: "data are essentially
# constant" / "not enough 'x' observations"; all zeros give t = NaN): NA.
# Run from this folder: Rscript make_score_golden.R
g17 <- function(x) ifelse(is.na(x), "NA", sprintf("%.17g", x))
d <- read.csv("scores.csv")
summarise <- function(x) {
  tt <- tryCatch(t.test(x, mu = 0), error = function(e) NULL)
  if (!is.null(tt) && is.nan(tt$statistic)) tt <- NULL
  data.frame(n = length(x), mean = g17(mean(x)), sd = g17(if (length(x) > 1) sd(x) else NA),
             t = g17(if (is.null(tt)) NA else unname(tt$statistic)),
             df = g17(if (is.null(tt)) NA else unname(tt$parameter)),
             p = g17(if (is.null(tt)) NA else tt$p.value),
             ci_low = g17(if (is.null(tt)) NA else tt$conf.int[1]),
             ci_high = g17(if (is.null(tt)) NA else tt$conf.int[2]))
}
groups <- unique(d$material)
rows <- do.call(rbind, lapply(groups, function(g) cbind(averaged = "rows", material = g,
                                                      summarise(d$response_oriented[d$material == g]))))
subj <- aggregate(response_oriented ~ participant + material, data = d, FUN = mean)
means <- do.call(rbind, lapply(groups, function(g) cbind(averaged = "participant", material = g,
                                                       summarise(subj$response_oriented[subj$material == g]))))
write.csv(rbind(rows, means), "score_golden.csv", row.names = FALSE, quote = FALSE)
print(rbind(rows, means))
