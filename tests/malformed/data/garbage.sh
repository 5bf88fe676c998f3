# A --program that answers every sample with a word instead of numbers.
while read -r line; do echo garbage; done
