// One view per block type, as in the window.
import ab from './ab.js';
import adjust from './adjust.js';
import bs1116 from './bs1116.js';
import changepoint from './changepoint.js';
import identify from './identify.js';
import instructions from './instructions.js';
import limits from './limits.js';
import magnitude from './magnitude.js';
import mushra from './mushra.js';
import questionnaire from './questionnaire.js';
import rating from './rating.js';
import staircase from './staircase.js';
import tokens from './tokens.js';

export const views = { ab, adjust, bs1116, changepoint, identify, instructions, limits, magnitude, mushra, questionnaire, rating,
  staircase, tokens };
