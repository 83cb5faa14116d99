// Magnitude estimation: the reference pair (its difference counts as the block's modulus value) first,
// then A and B; the participant types how different they sound. The server reads the number as the
// window does (decimal point or comma) and says why a value is refused.
import { el, note, prompt, soundButtons } from './common.js';

export default function magnitude(trial) {
  const page = trial.page;
  const m = page.modulus_value;
  const withModulus = page.modulus_count > 0;
  prompt(trial, withModulus && page.scale
    ? `First listen to the reference pair: the most different pair, counted as ${m}. Then listen to A and B and type how different they sound (${m / 2} = half as different).`
    : withModulus
    ? `First listen to the reference pair: its difference counts as ${m}. Then listen to A and B and type how different they sound (${m / 2} = half as different, ${m * 2} = twice as different).`
    : 'Listen to A and B and type how different they sound.');
  if (page.scale) note(trial, `Use the scale from ${page.scale.min} (identical) to ${page.scale.max} (as different as the reference pair).`);
  if (page.zero_allowed) note(trial, 'Type 0 if A and B sound exactly the same.');
  const all = page.sounds.map((_, i) => i);
  soundButtons(trial, all);
  const pair = all.slice(page.modulus_count);
  const entry = el('input', { type: 'text', id: 'magnitude', inputmode: 'decimal', autocomplete: 'off',
                              placeholder: withModulus ? `how different? (reference pair = ${m})` : 'how different?' });
  entry.addEventListener('input', () => trial.refresh());
  trial.root.append(entry);
  setTimeout(() => entry.focus(), 0);
  // The pair is playable once the reference pair was heard.
  trial.onRefresh = () => {
    const modulusHeard = all.slice(0, page.modulus_count).every((i) => trial.heard.has(i));
    for (const i of pair) trial.soundButtons[i].disabled = !modulusHeard;
  };
  return {
    answer: () => entry.value,
    complete: () => entry.value.trim() !== '',
    missing: 'Type a number.',
  };
}
