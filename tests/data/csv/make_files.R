# Writes the CSV files the readers must accept, with R itself (Rscript make_files.R, R 4.2, Debian 12).
# eurodist_r.csv: write.csv(as.matrix(eurodist)) - a labelled square matrix whose header starts with "".
write.csv(as.matrix(eurodist), "eurodist_r.csv")
# Golden values of classical MDS (cmdscale, 2 dimensions) and its eigenvalues, for the map check.
fit <- cmdscale(eurodist, k = 2, eig = TRUE)
write.csv(data.frame(label = rownames(fit$points), dim1 = fit$points[, 1], dim2 = fit$points[, 2]),
          "eurodist_cmdscale_golden.csv", row.names = FALSE)
write.csv(data.frame(eigenvalue = fit$eig[1:2]), "eurodist_eig_golden.csv", row.names = FALSE)
