# Golden values for the MUSHRA summary (tests/analysis/stats/test_mushra.cpp, tests/cli/test_cli_stats.cpp).
# A seeded MUSHRA result set (12 assessors x 8 items x 6 conditions) with planted screening cases,
# then BS.1534-3 post-screening and t-based 95 % intervals computed with base R (t.test).
# Run from this folder: Rscript make_golden.R
set.seed(1534)
conds <- c("reference", "e16", "e8", "lp", "anchor70", "anchor35")
truth <- c(reference = 97, e16 = 85, e8 = 70, lp = 55, anchor70 = 40, anchor35 = 20)
rows <- list()
for (p in 1:12) {
  for (t in 1:8) {
    for (c in conds) {
      r <- truth[[c]] + rnorm(1, 0, if (c == "reference") 2 else 9)
      if (c == "reference" && p == 3 && t %in% c(2, 5)) r <- 70 + t   # 2/8 items below 90: excluded
      if (c == "reference" && p == 7 && t == 4) r <- 80               # 1/8 items: kept
      if (c == "anchor70" && p == 9 && t %in% c(1, 2, 6)) r <- 95     # anchor check fails: reported
      r <- min(100, max(0, round(r)))
      rows[[length(rows) + 1]] <- data.frame(participant = sprintf("P%02d", p), trial = sprintf("item%d", t),
                                             condition = c, rating = r)
      # Assessor 5 rated item 3 twice (a repeated trial): the two ratings are averaged.
      if (p == 5 && t == 3)
        rows[[length(rows) + 1]] <- data.frame(participant = "P05", trial = "item3", condition = c,
                                               rating = min(100, max(0, round(r + rnorm(1, 0, 5)))))
    }
  }
}
d <- do.call(rbind, rows)
d <- d[sample(nrow(d)), ]
write.csv(d, "results.csv", row.names = FALSE, quote = FALSE)

m <- aggregate(rating ~ participant + trial + condition, data = d, FUN = mean)
ref <- m[m$condition == "reference", ]
miss <- tapply(ref$rating < 90, ref$participant, mean)
# Anchor check per anchor: fraction of items rated above 90.
a70 <- m[m$condition == "anchor70", ]; a35 <- m[m$condition == "anchor35", ]
f70 <- tapply(a70$rating > 90, a70$participant, mean)[names(miss)]
f35 <- tapply(a35$rating > 90, a35$participant, mean)[names(miss)]
screen <- data.frame(participant = names(miss), reference_fraction = as.vector(miss),
                     excluded = as.vector(miss > 0.15),
                     anchor70_fraction = as.vector(f70), anchor35_fraction = as.vector(f35),
                     anchor_fails = as.vector(f70 > 0.15 | f35 > 0.15))
write.csv(screen, "screening_golden.csv", row.names = FALSE, quote = FALSE)
keep <- m[!(m$participant %in% screen$participant[screen$excluded]), ]
g17 <- function(x) sprintf("%.17g", x)
summ <- function(v) { tt <- t.test(v); c(n = length(v), mean = mean(v), sd = sd(v),
                                         ci_low = tt$conf.int[1], ci_high = tt$conf.int[2]) }
out <- do.call(rbind, lapply(conds, function(c) {
  s <- summ(keep$rating[keep$condition == c])
  data.frame(item = "ALL", condition = c, n = s[["n"]], mean = g17(s[["mean"]]), sd = g17(s[["sd"]]),
             ci_low = g17(s[["ci_low"]]), ci_high = g17(s[["ci_high"]]))
}))
for (t in sort(unique(keep$trial))) for (c in conds) {
  s <- summ(keep$rating[keep$condition == c & keep$trial == t])
  out <- rbind(out, data.frame(item = t, condition = c, n = s[["n"]], mean = g17(s[["mean"]]), sd = g17(s[["sd"]]),
                               ci_low = g17(s[["ci_low"]]), ci_high = g17(s[["ci_high"]])))
}
write.csv(out, "summary_golden.csv", row.names = FALSE, quote = FALSE)
print(screen)
