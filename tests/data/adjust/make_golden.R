# Golden values for `modalstudy stats adjust` (analysis/stats/adjust_summary.cpp) on adjust.csv, from R's
# own functions: quantile(type = 7) for the quartiles; the whiskers at the furthest observation within
# 1.5 IQR of the box and the outliers beyond (Tukey's fences on those quartiles, as matplotlib draws a
# box; R's boxplot() itself uses fivenum's hinges); mean, sd; log10(chosen / true) where true is known.
# One answer = participant, session, block, trial (its rows share plays and rt_ms). Writes golden.csv:
# group, object, key ("" for time and plays), measure, stat, value (outliers ';'-separated, %.17g).
# Usage: Rscript tests/data/adjust/make_golden.R  (from the repository)
d <- read.csv("tests/data/adjust/adjust.csv", stringsAsFactors = FALSE, na.strings = "NA")
d$answer <- paste(d$participant, d$session, d$block, d$trial)
f <- function(x) sprintf("%.17g", x)
box <- function(x) {
  q <- quantile(x, c(0.25, 0.5, 0.75), type = 7, names = FALSE)
  fence <- 1.5 * (q[3] - q[1])
  inside <- x[x >= q[1] - fence & x <= q[3] + fence]
  out <- sort(x[x < q[1] - fence | x > q[3] + fence])
  c(n = f(length(x)), lower_whisker = f(min(inside, q[1])), q1 = f(q[1]), median = f(q[2]), q3 = f(q[3]),
    upper_whisker = f(max(inside, q[3])), outliers = paste(f(out), collapse = ";"))
}
rows <- list()
add <- function(group, object, key, measure, stats) {
  for (s in names(stats)) rows[[length(rows) + 1]] <<- data.frame(group = group, object = object, key = key,
                                                                   measure = measure, stat = s, value = stats[[s]])
}
answers <- d[!duplicated(d$answer), ]
for (g in unique(d$section)) {
  for (o in unique(d$object[d$section == g])) {
    a <- answers[answers$section == g & answers$object == o, ]
    add(g, o, "", "time_s", box(a$rt_ms / 1000))
    add(g, o, "", "plays", box(a$plays))
    dd <- d[d$section == g & d$object == o, ]
    for (k in unique(dd$key)) {
      x <- dd$value[dd$key == k]
      add(g, o, k, "chosen", c(box(x), mean = f(mean(x)), sd = f(sd(x))))
      truth <- unique(dd$truth[dd$key == k])
      if (!is.na(truth)) {
        r <- log10(x[x > 0] / truth)
        add(g, o, k, "log10_ratio", c(box(r), mean = f(mean(r)), rms = f(sqrt(mean(r^2))),
                                      not_positive = f(sum(x <= 0))))
      }
    }
  }
  a <- answers[answers$section == g, ]
  add(g, "", "", "time_s", box(a$rt_ms / 1000))
  add(g, "", "", "plays", box(a$plays))
}
out <- do.call(rbind, rows)
write.csv(out, "tests/data/adjust/golden.csv", row.names = FALSE)
