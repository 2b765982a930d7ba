// Issue 7: #fopen ... read may not open a file outside the allowed tree.
#fopen F "/etc/passwd" read
