# Writes the CSV files the readers must accept, with pandas itself (python3 make_files.py; Debian 12's
# python3-pandas 1.5). Reads R's eurodist written by make_files.R.
import csv
import pandas as pd

d = pd.read_csv("eurodist_r.csv", index_col=0)
# to_csv(): the index as an unnamed first column, so the header starts with an empty cell.
d.to_csv("eurodist_pandas.csv")
# The same with a UTF-8 byte-order mark (what Excel wants), CRLF line ends and every field quoted.
d.to_csv("eurodist_pandas_bom_quoted.csv", encoding="utf-8-sig", lineterminator="\r\n", quoting=csv.QUOTE_ALL)
# A modes table as a spreadsheet user writes it: BOM, quoted fields, CRLF, an extra text column.
modes = pd.DataFrame({"freq_hz": [440.0, 1234.5, 2500.0], "decay_per_s": [6.0, 12.5, 30.0],
                      "amp": [0.5, 0.25, 0.125], "note": ["fundamental", "a, b", "say \"hi\""]})
modes.to_csv("modes_pandas_bom_quoted.csv", index=False, encoding="utf-8-sig", lineterminator="\r\n",
             quoting=csv.QUOTE_ALL)
